// `opentop-cli eol results` and `eol certificate` on a real SQLite results database filled
// through ResultStore, as a station fills it.
#include "cli/ExitCode.h"
#include "model/eol/ResultCsv.h"
#include "model/eol/ResultDatabase.h"
#include "model/eol/ResultQueries.h"
#include "model/eol/ResultStore.h"
#include "tests/cli/CliTestSupport.h"
#include "tests/support/EolSampleUnit.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTimeZone>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

class EolResultsCommand : public ::testing::Test
{
protected:
    void SetUp() override
    {
        ASSERT_TRUE(dir.isValid());
        db = dir.filePath(QStringLiteral("results.db"));
        QString error;
        std::unique_ptr<ResultDatabase> database = ResultDatabase::open(db, &error);
        ASSERT_TRUE(database) << qPrintable(error);
        ResultStore store(*database);
        const QDateTime base(QDate(2026, 11, 24), QTime(13, 0), QTimeZone::utc());
        // A: S1 passes; S2 fails, then passes its retest; S3's station died mid-unit.
        // B (another recipe and station): S4 aborted.
        auto add = [&](const char* serial, UnitStatus status, int minute, const char* recipe,
                       const char* station) {
            UnitRecord u = test::eolSampleUnit(QString::fromLatin1(serial), status);
            u.recipeName = QString::fromLatin1(recipe);
            u.station = QString::fromLatin1(station);
            u.started = base.addSecs(60 * minute);
            u.ended = u.started.addSecs(40);
            if (status == UnitStatus::Aborted)
                u.failureReason = QStringLiteral("cancelled by the operator");
            ASSERT_TRUE(store.beginUnit(u, &error)) << qPrintable(error);
            if (status != UnitStatus::Interrupted) {
                ASSERT_TRUE(store.finishUnit(u, &error)) << qPrintable(error);
            }
            stored << u;
        };
        add("S1", UnitStatus::Pass, 0, "pump A", "station-1");
        add("S2", UnitStatus::Fail, 2, "pump A", "station-1");
        add("S3", UnitStatus::Interrupted, 4, "pump A", "station-1");
        add("S2", UnitStatus::Pass, 6, "pump A", "station-1");
        add("S4", UnitStatus::Aborted, 8, "pump B", "station-2");
        ASSERT_EQ(store.markInterrupted(QStringLiteral("station-1"), base.addSecs(3600), &error), 1)
            << qPrintable(error);
        stored[2].status = UnitStatus::Interrupted;
    }

    CliRun results(QStringList args) const
    {
        return runCli(QStringList{QStringLiteral("eol"), QStringLiteral("results"),
                                  QStringLiteral("--db"), db} +
                      args);
    }

    // The serials of the table's rows, in order.
    static QStringList serials(const CliRun& r)
    {
        QStringList list;
        const QStringList lines = r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        for (int i = 1; i < lines.size() - 1; ++i)
            list << lines.at(i).simplified().split(QLatin1Char(' ')).value(2);
        return list;
    }

    std::optional<UnitRecord> whole(int index) const
    {
        QString error;
        std::unique_ptr<ResultDatabase> database = ResultDatabase::open(db, &error);
        if (!database)
            return std::nullopt;
        return ResultQueries(*database).load(stored.at(index).id, &error);
    }

    QTemporaryDir dir;
    QString db;
    QVector<UnitRecord> stored;
};

} // namespace

TEST_F(EolResultsCommand, FiltersBySerialVerdictRecipeStationAndTime)
{
    CliRun r = results({});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_EQ(serials(r),
              (QStringList{QStringLiteral("S1"), QStringLiteral("S2"), QStringLiteral("S3"),
                           QStringLiteral("S2"), QStringLiteral("S4")}))
        << qPrintable(r.out);
    EXPECT_TRUE(r.out.contains(QStringLiteral("INTERRUPTED"))) << qPrintable(r.out);
    EXPECT_TRUE(r.out.contains(QStringLiteral("drive 2: speed min 1203 r/min below 1450 r/min")))
        << qPrintable(r.out);
    EXPECT_TRUE(r.out.contains(QStringLiteral("5 unit(s)"))) << qPrintable(r.out);

    EXPECT_EQ(serials(results({QStringLiteral("--serial"), QStringLiteral("S2")})),
              (QStringList{QStringLiteral("S2"), QStringLiteral("S2")}));
    r = results({QStringLiteral("--verdict"), QStringLiteral("fail")});
    EXPECT_EQ(serials(r), QStringList{QStringLiteral("S2")}) << qPrintable(r.out);
    EXPECT_EQ(serials(results({QStringLiteral("--verdict"), QStringLiteral("interrupted")})),
              QStringList{QStringLiteral("S3")});
    EXPECT_EQ(serials(results({QStringLiteral("--verdict"), QStringLiteral("pass")})),
              (QStringList{QStringLiteral("S1"), QStringLiteral("S2")}));
    EXPECT_EQ(serials(results({QStringLiteral("--recipe"), QStringLiteral("pump B")})),
              QStringList{QStringLiteral("S4")});
    EXPECT_EQ(serials(results({QStringLiteral("--station"), QStringLiteral("station-2")})),
              QStringList{QStringLiteral("S4")});
    EXPECT_EQ(serials(results({QStringLiteral("--limit"), QStringLiteral("2")})),
              (QStringList{QStringLiteral("S2"), QStringLiteral("S4")}));
    r = results({QStringLiteral("--since"), QStringLiteral("2026-11-24T13:03Z"),
                 QStringLiteral("--until"), QStringLiteral("2026-11-24 13:07:00Z")});
    EXPECT_EQ(serials(r), (QStringList{QStringLiteral("S3"), QStringLiteral("S2")}))
        << qPrintable(r.out + r.err);
    r = results({QStringLiteral("--serial"), QStringLiteral("nobody")});
    EXPECT_EQ(r.code, ExitOk);
    EXPECT_TRUE(r.out.contains(QStringLiteral("no unit matches"))) << qPrintable(r.out);

    r = results({QStringLiteral("--verdict"), QStringLiteral("fail"), QStringLiteral("--json")});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    const QJsonArray units =
        QJsonDocument::fromJson(r.out.toUtf8()).object().value(QStringLiteral("units")).toArray();
    ASSERT_EQ(units.size(), 1) << qPrintable(r.out);
    EXPECT_EQ(units.at(0).toObject().value(QStringLiteral("id")).toString(), stored.at(1).id);
}

TEST_F(EolResultsCommand, CsvToStandardOutputAndToAFile)
{
    CliRun r =
        results({QStringLiteral("--csv"), QStringLiteral("--recipe"), QStringLiteral("pump A")});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    const QStringList lines = r.out.split(QStringLiteral("\r\n"), Qt::SkipEmptyParts);
    ASSERT_EQ(lines.size(), 5) << qPrintable(r.out);
    EXPECT_TRUE(lines.at(0).startsWith(QStringLiteral("unit_id,serial,")))
        << qPrintable(lines.at(0));
    EXPECT_TRUE(lines.at(2).contains(stored.at(1).id));
    EXPECT_TRUE(lines.at(2).contains(QStringLiteral(",fail,"))) << qPrintable(lines.at(2));

    const QString file = dir.filePath(QStringLiteral("units.csv"));
    r = results({QStringLiteral("--csv"), QStringLiteral("-o"), file});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_TRUE(r.out.isEmpty());
    QFile f(file);
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    QString error;
    std::unique_ptr<ResultDatabase> database = ResultDatabase::open(db, &error);
    ASSERT_TRUE(database) << qPrintable(error);
    const auto all = ResultQueries(*database).find(ResultFilter(), &error);
    ASSERT_TRUE(all) << qPrintable(error);
    EXPECT_EQ(f.readAll(), ResultCsv::units(*all));
}

TEST_F(EolResultsCommand, YieldPerRecipeAndShiftWithFailureReasons)
{
    CliRun r = results(
        {QStringLiteral("--yield"), QStringLiteral("--shifts"), QStringLiteral("06:00,18:00")});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    // pump A: S1 and S2 got verdicts (S3's station died: no verdict); only S1 passed the first
    // time, S2 at its second; 4 records, 1 unfinished. pump B: S4 aborted, no verdict.
    bool found = false;
    for (const QString& line : r.out.split(QLatin1Char('\n'))) {
        if (line.startsWith(QStringLiteral("pump A")) && !found) {
            EXPECT_EQ(
                line.simplified(),
                QStringLiteral("pump A rev. 7b 2 1 (50.0 %) 2 (100.0 %) 2 (100.0 %) 2 1 0 1"));
            found = true;
        }
    }
    EXPECT_TRUE(found) << qPrintable(r.out);
    EXPECT_TRUE(r.out.contains(QStringLiteral("Per shift"))) << qPrintable(r.out);
    EXPECT_TRUE(
        r.out.contains(QStringLiteral("pump A rev. 7b: drive 2: speed min 1203 r/min below")))
        << qPrintable(r.out);
    const int stationPart = r.out.indexOf(QStringLiteral("Station errors (not counted in yield)"));
    ASSERT_GT(stationPart, 0) << qPrintable(r.out);
    EXPECT_GT(r.out.indexOf(QStringLiteral("pump B rev. 7b: cancelled by the operator")),
              stationPart)
        << qPrintable(r.out);

    r = results({QStringLiteral("--yield"), QStringLiteral("--csv")});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_TRUE(
        r.out.startsWith(QStringLiteral("recipe,revision,checksum,shift,serials,first_pass,")))
        << qPrintable(r.out);
    EXPECT_TRUE(r.out.contains(QStringLiteral(",,0,0,0,0,0,0,0,1,0,0,1,0,station,cancelled by the "
                                              "operator,1")))
        << qPrintable(r.out);

    r = results({QStringLiteral("--yield"), QStringLiteral("--json")});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    const QJsonArray rows = QJsonDocument::fromJson(r.out.toUtf8())
                                .object()
                                .value(QStringLiteral("perRecipe"))
                                .toArray();
    ASSERT_EQ(rows.size(), 2) << qPrintable(r.out);
    const QJsonObject a = rows.at(0).toObject();
    EXPECT_NEAR(a.value(QStringLiteral("firstPassYield")).toDouble(), 0.5, 1e-9);
    EXPECT_NEAR(a.value(QStringLiteral("secondPassYield")).toDouble(), 1.0, 1e-9);
    EXPECT_EQ(a.value(QStringLiteral("checksum")).toString(), stored.at(0).recipeChecksum);
    EXPECT_EQ(rows.at(1).toObject().value(QStringLiteral("stationErrors")).toInt(), 1);

    // One recipe version: its checksum selects it.
    r = results({QStringLiteral("--yield"), QStringLiteral("--json"), QStringLiteral("--checksum"),
                 QStringLiteral("sha256:none")});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_TRUE(QJsonDocument::fromJson(r.out.toUtf8())
                    .object()
                    .value(QStringLiteral("perRecipe"))
                    .toArray()
                    .isEmpty())
        << qPrintable(r.out);
}

TEST_F(EolResultsCommand, WrongArgumentsAndDatabasesAreClearErrors)
{
    struct Case
    {
        QStringList args;
        int code;
        const char* says;
    };
    const QVector<Case> cases{
        {{QStringLiteral("--verdict"), QStringLiteral("maybe")}, ExitUsage, "--verdict \"maybe\""},
        {{QStringLiteral("--since"), QStringLiteral("last tuesday")}, ExitUsage, "--since"},
        {{QStringLiteral("--limit"), QStringLiteral("0")}, ExitUsage, "--limit"},
        {{QStringLiteral("--shifts"), QStringLiteral("06:00")}, ExitUsage, "--yield"},
        {{QStringLiteral("--csv"), QStringLiteral("--json")}, ExitUsage, "not both"},
        {{QStringLiteral("-o"), QStringLiteral("x.csv")}, ExitUsage, "--csv"},
        {{QStringLiteral("extra")}, ExitUsage, "unexpected argument"},
    };
    for (const Case& c : cases) {
        const CliRun r = results(c.args);
        EXPECT_EQ(r.code, c.code) << qPrintable(c.args.join(QLatin1Char(' ')) + r.err);
        EXPECT_TRUE(r.err.contains(QString::fromUtf8(c.says)))
            << qPrintable(c.args.join(QLatin1Char(' ')) + QStringLiteral(": ") + r.err);
    }
    const QString missing = dir.filePath(QStringLiteral("none.db"));
    CliRun r =
        runCli({QStringLiteral("eol"), QStringLiteral("results"), QStringLiteral("--db"), missing});
    EXPECT_EQ(r.code, ExitCommunication); // cannot be opened, as a junk file or a lost server
    EXPECT_TRUE(r.err.contains(QStringLiteral("no results database at %1").arg(missing)))
        << qPrintable(r.err);
    EXPECT_FALSE(QFile::exists(missing));

    const QString junk = dir.filePath(QStringLiteral("junk.db"));
    QFile f(junk);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(QByteArray(4096, 'x'));
    f.close();
    r = runCli({QStringLiteral("eol"), QStringLiteral("results"), QStringLiteral("--db"), junk});
    EXPECT_EQ(r.code, ExitCommunication);
    EXPECT_TRUE(r.err.startsWith(QStringLiteral("error: "))) << qPrintable(r.err);

    // A server that is not there: named, its password never shown.
    r = runCli({QStringLiteral("eol"), QStringLiteral("results"), QStringLiteral("--db"),
                QStringLiteral("postgresql://quality:s3cret@127.0.0.1:1/line?connect_timeout=2")});
    EXPECT_EQ(r.code, ExitCommunication);
    EXPECT_TRUE(r.err.contains(QStringLiteral("quality@127.0.0.1:1"))) << qPrintable(r.err);
    EXPECT_FALSE(r.err.contains(QStringLiteral("s3cret"))) << qPrintable(r.err);
}

TEST_F(EolResultsCommand, DefaultDatabaseIsTheSqliteFileInTheUsersDataFolder)
{
    const QByteArray oldHome = qgetenv("XDG_DATA_HOME");
    const QByteArray oldDb = qgetenv("OPENTOP_EOL_DB");
    qputenv("XDG_DATA_HOME", dir.filePath(QStringLiteral("data")).toUtf8());
    qunsetenv("OPENTOP_EOL_DB");
    const QString expected = dir.filePath(QStringLiteral("data/opentop/results.db"));
    CliRun r = runCli({QStringLiteral("eol"), QStringLiteral("results")});
    EXPECT_EQ(r.code, ExitCommunication); // not there yet: cannot be opened
    EXPECT_TRUE(r.err.contains(expected)) << qPrintable(r.err);
    ASSERT_TRUE(QDir().mkpath(QFileInfo(expected).absolutePath()));
    ASSERT_TRUE(QFile::copy(db, expected));
    r = runCli({QStringLiteral("eol"), QStringLiteral("results"), QStringLiteral("--serial"),
                QStringLiteral("S4")});
    EXPECT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_EQ(serials(r), QStringList{QStringLiteral("S4")}) << qPrintable(r.out);
    // OPENTOP_EOL_DB names another.
    qputenv("OPENTOP_EOL_DB", dir.filePath(QStringLiteral("elsewhere.db")).toUtf8());
    r = runCli({QStringLiteral("eol"), QStringLiteral("results")});
    EXPECT_EQ(r.code, ExitCommunication);
    EXPECT_TRUE(r.err.contains(QStringLiteral("elsewhere.db"))) << qPrintable(r.err);
    qputenv("XDG_DATA_HOME", oldHome);
    if (oldDb.isEmpty())
        qunsetenv("OPENTOP_EOL_DB");
    else
        qputenv("OPENTOP_EOL_DB", oldDb);
}

TEST_F(EolResultsCommand, CertificateJsonIsTheStoredRecord)
{
    CliRun r = runCli({QStringLiteral("eol"), QStringLiteral("certificate"), QStringLiteral("S2"),
                       QStringLiteral("--db"), db, QStringLiteral("--json")});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    QString error;
    const std::optional<UnitRecord> printed = UnitRecordJson::fromBytes(r.out.toUtf8(), &error);
    ASSERT_TRUE(printed) << qPrintable(error);
    const std::optional<UnitRecord> newest = whole(3);
    ASSERT_TRUE(newest);
    EXPECT_EQ(*printed, *newest);
    EXPECT_EQ(printed->status, UnitStatus::Pass);
    EXPECT_EQ(printed->writtenValues.size(), 3);

    // --id: an older record of the serial, written to a file.
    const QString file = dir.filePath(QStringLiteral("s2-first.json"));
    r = runCli({QStringLiteral("eol"), QStringLiteral("certificate"), QStringLiteral("--id"),
                stored.at(1).id, QStringLiteral("--db"), db, QStringLiteral("--json"),
                QStringLiteral("-o"), file});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    QFile f(file);
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    const std::optional<UnitRecord> first = UnitRecordJson::fromBytes(f.readAll(), &error);
    ASSERT_TRUE(first) << qPrintable(error);
    EXPECT_EQ(*first, *whole(1));
    EXPECT_EQ(first->status, UnitStatus::Fail);
    EXPECT_EQ(first->traffic.size(), 3);
}

TEST_F(EolResultsCommand, CertificateOfAnUnknownSerialOrRecordIsAnError)
{
    CliRun r = runCli({QStringLiteral("eol"), QStringLiteral("certificate"), QStringLiteral("S99"),
                       QStringLiteral("--db"), db, QStringLiteral("--json")});
    EXPECT_EQ(r.code, ExitInvalid);
    EXPECT_TRUE(r.err.contains(QStringLiteral("no record of serial number S99")))
        << qPrintable(r.err);
    EXPECT_TRUE(r.out.isEmpty());
    r = runCli({QStringLiteral("eol"), QStringLiteral("certificate"), QStringLiteral("--id"),
                QStringLiteral("no-such-id"), QStringLiteral("--db"), db,
                QStringLiteral("--json")});
    EXPECT_EQ(r.code, ExitInvalid);
    EXPECT_TRUE(r.err.contains(QStringLiteral("no-such-id"))) << qPrintable(r.err);
    r = runCli({QStringLiteral("eol"), QStringLiteral("certificate"), QStringLiteral("--db"), db});
    EXPECT_EQ(r.code, ExitUsage);
    EXPECT_TRUE(r.err.contains(QStringLiteral("name one serial number"))) << qPrintable(r.err);
}

TEST_F(EolResultsCommand, CertificatePdfFromTheProgram)
{
    // The program itself: it makes the (offscreen) GUI application a PDF needs.
    const QString program = QStringLiteral(OPENTOP_BIN_DIR "/opentop-cli");
    ASSERT_TRUE(QFile::exists(program)) << qPrintable(program);
    const QString file = dir.filePath(QStringLiteral("s2.pdf"));
    QProcess p;
    p.setWorkingDirectory(dir.path());
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove(QStringLiteral("DISPLAY"));
    env.remove(QStringLiteral("QT_QPA_PLATFORM"));
    p.setProcessEnvironment(env);
    p.start(program, {QStringLiteral("eol"), QStringLiteral("certificate"), QStringLiteral("--id"),
                      stored.at(1).id, QStringLiteral("--db"), db, QStringLiteral("-o"), file});
    ASSERT_TRUE(p.waitForFinished(60000));
    EXPECT_EQ(p.exitStatus(), QProcess::NormalExit);
    ASSERT_EQ(p.exitCode(), ExitOk) << p.readAllStandardError().toStdString();
    EXPECT_TRUE(QString::fromUtf8(p.readAllStandardOutput())
                    .contains(QStringLiteral("serial number S2, FAIL")));
    QFile f(file);
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    EXPECT_TRUE(f.read(5).startsWith("%PDF-"));
    f.close();

    // Without -o: SERIAL.pdf in the current folder, the newest record (a pass).
    p.start(program, {QStringLiteral("eol"), QStringLiteral("certificate"), QStringLiteral("S2"),
                      QStringLiteral("--db"), db});
    ASSERT_TRUE(p.waitForFinished(60000));
    ASSERT_EQ(p.exitCode(), ExitOk) << p.readAllStandardError().toStdString();
    const QString newest = dir.filePath(QStringLiteral("S2.pdf"));
    ASSERT_TRUE(QFile::exists(newest));

    const QString pdftotext = QStandardPaths::findExecutable(QStringLiteral("pdftotext"));
    if (pdftotext.isEmpty())
        return;
    auto text = [&](const QString& pdf) {
        QProcess t;
        t.start(pdftotext, {pdf, QStringLiteral("-")});
        t.waitForFinished(30000);
        return QString::fromUtf8(t.readAllStandardOutput());
    };
    const QString failed = text(file);
    EXPECT_TRUE(failed.contains(QStringLiteral("S2"))) << qPrintable(failed);
    EXPECT_TRUE(failed.contains(QStringLiteral("FAIL"))) << qPrintable(failed);
    EXPECT_TRUE(failed.contains(QStringLiteral("1203 r/min below 1450"))) << qPrintable(failed);
    // The PASS names the FAIL before it (issue 25 item 6).
    const QString passed = text(newest);
    EXPECT_TRUE(passed.contains(QStringLiteral("PASS"))) << qPrintable(passed);
    EXPECT_TRUE(passed.contains(QStringLiteral("This serial failed 1 earlier test")))
        << qPrintable(passed);
    EXPECT_TRUE(passed.contains(QStringLiteral("Earlier tests of this serial")))
        << qPrintable(passed);
}

TEST_F(EolResultsCommand, CertificatePdfInAProgramWithoutGuiIsRefusedCleanly)
{
    const CliRun r = runCli({QStringLiteral("eol"), QStringLiteral("certificate"),
                             QStringLiteral("S1"), QStringLiteral("--db"), db, QStringLiteral("-o"),
                             dir.filePath(QStringLiteral("x.pdf"))});
    EXPECT_EQ(r.code, ExitUsage);
    EXPECT_TRUE(r.err.contains(QStringLiteral("--json"))) << qPrintable(r.err);
    EXPECT_FALSE(QFile::exists(dir.filePath(QStringLiteral("x.pdf"))));
}
