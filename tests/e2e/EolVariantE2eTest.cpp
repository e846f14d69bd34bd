// The drive's variant over a real port: `opentop-cli eol run` on a pseudo-terminal against
// opentop-sim, whose DBUs report only "DBU" as real ones do. The shipped example recipes pass
// with the matching drives (a mixed DBU200/DBU400 unit included); a DBU400 at a DBU200
// position never passes as a DBU200, and the probe leaves its registers as they were;
// --variant outside the recipe is refused before anything is sent.
#include "model/eol/RecipeFile.h"
#include "model/eol/ResultDatabase.h"
#include "model/eol/ResultQueries.h"
#include "tests/e2e/CliProcess.h"
#include "tests/e2e/SimProcess.h"

#include <QElapsedTimer>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

using namespace opentop;
using namespace opentop::test;

namespace {

constexpr int kLowerLimit = 0x1009; // DBU core.lower_limit (fc 03): the variant probe's setting

QString example(const char* name)
{
    return QStringLiteral(OPENTOP_SOURCE_DIR "/docs/examples/") + QString::fromLatin1(name);
}

// `eol run` of `recipe` with every per-unit value in the middle of its range.
CliResult runUnit(const QString& port, const QString& recipePath, const QString& serial,
                  const QString& db, const QStringList& extra = {})
{
    QString error;
    const std::optional<Recipe> recipe = RecipeFile::load(recipePath, &error);
    EXPECT_TRUE(recipe) << error.toStdString();
    QStringList args{QStringLiteral("eol"),
                     QStringLiteral("run"),
                     recipePath,
                     QStringLiteral("--serial"),
                     serial,
                     QStringLiteral("--db"),
                     db,
                     QStringLiteral("--station"),
                     QStringLiteral("e2e"),
                     QStringLiteral("--json")};
    for (const RecipePosition& p : recipe ? recipe->positions : QVector<RecipePosition>())
        for (const RecipeUnitValue& u : p.unitValues)
            args << QStringLiteral("--value")
                 << QStringLiteral("%1:%2=%3")
                        .arg(p.machineNumber)
                        .arg(u.name)
                        .arg(std::round((u.min + u.max) / 2));
    return runCliOn(port, args + extra, 120000);
}

QJsonObject resultOf(const QString& out)
{
    QJsonObject found;
    for (const QString& line : out.split(QLatin1Char('\n'), Qt::SkipEmptyParts)) {
        const QJsonObject o = QJsonDocument::fromJson(line.toUtf8()).object();
        if (o.value(QStringLiteral("event")).toString() == QLatin1String("result"))
            found = o;
    }
    return found;
}

std::optional<UnitRecord> recordOf(const QString& db, const QString& serial)
{
    QString error;
    const std::unique_ptr<ResultDatabase> database = ResultDatabase::open(db, &error);
    if (!database)
        return std::nullopt;
    const auto history = ResultQueries(*database).history(serial, &error);
    if (!history || history->isEmpty())
        return std::nullopt;
    return history->last();
}

class EolVariantE2e : public ::testing::Test
{
protected:
    void start(const QString& devices)
    {
        QString error;
        ASSERT_TRUE(sim.start({QStringLiteral("--devices"), devices}, &error))
            << error.toStdString();
        db = dir.filePath(QStringLiteral("results.db"));
    }

    SimProcess sim;
    QTemporaryDir dir;
    QString db;
};

} // namespace

TEST_F(EolVariantE2e, TheExampleDbu200RecipePassesAndTheRecordSaysTheVariantWasProbed)
{
    start(QStringLiteral("dbu200@1"));
    const CliResult r = runUnit(sim.pty, example("recipe-dbu200.json"), QStringLiteral("SN-1"), db);
    ASSERT_EQ(r.code, 0) << (r.out + r.err).toStdString();
    const auto record = recordOf(db, QStringLiteral("SN-1"));
    ASSERT_TRUE(record);
    ASSERT_EQ(record->drives.size(), 1);
    EXPECT_EQ(record->drives[0].variant, QStringLiteral("dbu200"));
    EXPECT_EQ(record->drives[0].variantSource, VariantSource::Probed);
    EXPECT_EQ(sim.get(1, kLowerLimit, 3), 0); // the probe's value written back
}

TEST_F(EolVariantE2e, TheEightDriveExamplePassesWithDbu200sAndDbu400sMixed)
{
    start(QStringLiteral("dbu200@1-4,dbu400@5-8"));
    const CliResult r =
        runUnit(sim.pty, example("recipe-eight-dbu.json"), QStringLiteral("SN-8"), db);
    ASSERT_EQ(r.code, 0) << (r.out + r.err).toStdString();
    const auto record = recordOf(db, QStringLiteral("SN-8"));
    ASSERT_TRUE(record);
    ASSERT_EQ(record->drives.size(), 8);
    for (const UnitDrive& d : record->drives) {
        EXPECT_EQ(d.variant,
                  d.machineNumber <= 4 ? QStringLiteral("dbu200") : QStringLiteral("dbu400"))
            << d.machineNumber;
        EXPECT_EQ(d.variantSource, VariantSource::Probed) << d.machineNumber;
        EXPECT_EQ(sim.get(d.machineNumber, kLowerLimit, 3), 0) << d.machineNumber;
    }
}

TEST_F(EolVariantE2e, TheDcControllerExamplePasses)
{
    start(QStringLiteral("dcpid@7"));
    // The simulator's pty takes the command line's default line format, as the other e2e tests.
    const CliResult r = runUnit(sim.pty, example("recipe-dcpid.json"), QStringLiteral("SN-D"), db);
    ASSERT_EQ(r.code, 0) << (r.out + r.err).toStdString();
}

TEST_F(EolVariantE2e, ADbu400AtADbu200PositionNeverPassesAsADbu200)
{
    start(QStringLiteral("dbu400@1"));
    const int lowerBefore = sim.get(1, kLowerLimit, 3);
    const CliResult r = runUnit(sim.pty, example("recipe-dbu200.json"), QStringLiteral("SN-4"), db);
    EXPECT_NE(r.code, 0) << (r.out + r.err).toStdString();
    const QJsonObject result = resultOf(r.out);
    EXPECT_NE(result.value(QStringLiteral("status")).toString(), QStringLiteral("pass"));
    const QString reason = result.value(QStringLiteral("reason")).toString();
    EXPECT_TRUE(reason.contains(QStringLiteral("DBU400")) &&
                reason.contains(QStringLiteral("DBU200")))
        << r.out.toStdString();
    const auto record = recordOf(db, QStringLiteral("SN-4"));
    ASSERT_TRUE(record);
    ASSERT_EQ(record->drives.size(), 1);
    EXPECT_EQ(record->drives[0].variant, QStringLiteral("dbu400"));
    EXPECT_EQ(record->drives[0].variantSource, VariantSource::Probed);
    EXPECT_TRUE(record->writtenValues.isEmpty());
    EXPECT_EQ(sim.get(1, kLowerLimit, 3), lowerBefore);
}

TEST_F(EolVariantE2e, AVariantTheRecipeDoesNotAllowIsRefusedBeforeAnythingIsSent)
{
    start(QStringLiteral("dbu200@1"));
    const CliResult r = runUnit(sim.pty, example("recipe-dbu200.json"), QStringLiteral("SN-V"), db,
                                {QStringLiteral("--variant"), QStringLiteral("dbu400")});
    EXPECT_EQ(r.code, 2) << (r.out + r.err).toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("nothing was sent"))) << r.err.toStdString();
    EXPECT_FALSE(recordOf(db, QStringLiteral("SN-V")));
}

// kill -9 between the probe and its write-back leaves a DBU200 with a speed lower limit of
// 280 r/min. The probe journal keeps the original on disk first: the restarted station's next
// run of the unit puts it back before it probes again, and the record says so.
TEST_F(EolVariantE2e, AStationKilledMidProbeHasTheSettingPutBackByTheNextRun)
{
    QString error;
    // At 9600 baud on a timed line, a probe and its write-back are some 40 ms apart: the test
    // sees the probe's frame in the simulator's trace and kills the station in between.
    ASSERT_TRUE(sim.start({QStringLiteral("--devices"), QStringLiteral("dbu200@1"),
                           QStringLiteral("--baud"), QStringLiteral("9600"),
                           QStringLiteral("--wire-timing")},
                          &error, false))
        << error.toStdString();
    db = dir.filePath(QStringLiteral("results.db"));
    qputenv("XDG_DATA_HOME", dir.filePath(QStringLiteral("data")).toLocal8Bit());
    const int original = sim.get(1, kLowerLimit, 3);
    ASSERT_NE(original, 280);
    const QStringList line{QStringLiteral("--baud"), QStringLiteral("9600")};
    QStringList args{QStringLiteral("--port"), sim.pty};
    args << line << QStringLiteral("eol") << QStringLiteral("run") << example("recipe-dbu200.json")
         << QStringLiteral("--serial") << QStringLiteral("SN-K") << QStringLiteral("--db") << db
         << QStringLiteral("--station") << QStringLiteral("e2e") << QStringLiteral("--value")
         << QStringLiteral("1:spno3.speed=1500");
    // The probe's write of 280 (0x0118) to 0x1009, as function 06 or 16.
    static const QRegularExpression probe(
        QStringLiteral("rx 01 (06 10 09|10 10 09 00 01 02) 01 18"));
    bool killed = false;
    for (int attempt = 0; attempt < 3 && !killed; ++attempt) {
        QProcess station;
        station.start(cliProgram(), args);
        ASSERT_TRUE(station.waitForStarted(5000));
        QString trace;
        QElapsedTimer timer;
        timer.start();
        while (timer.elapsed() < 30000 && station.state() != QProcess::NotRunning) {
            sim.process().waitForReadyRead(1);
            trace += QString::fromLocal8Bit(sim.process().readAllStandardError());
            if (probe.match(trace).hasMatch()) {
                station.kill();
                break;
            }
        }
        station.waitForFinished(5000);
        killed = sim.get(1, kLowerLimit, 3) == 280;
    }
    ASSERT_TRUE(killed) << "the station was never killed between the probe and its write-back";

    // The restarted station: the unit again, on a normal line.
    const CliResult r =
        runUnit(sim.pty, example("recipe-dbu200.json"), QStringLiteral("SN-K"), db, line);
    EXPECT_EQ(r.code, 0) << (r.out + r.err).toStdString();
    EXPECT_EQ(sim.get(1, kLowerLimit, 3), original);
    const auto record = recordOf(db, QStringLiteral("SN-K"));
    ASSERT_TRUE(record);
    ASSERT_EQ(record->drives.size(), 1);
    EXPECT_TRUE(record->drives[0].variantProof.contains(QStringLiteral("set back from 280")))
        << record->drives[0].variantProof.toStdString();
    EXPECT_EQ(record->drives[0].variantSource, VariantSource::Probed);
    // The journal is empty again: a third run touches nothing it need not.
    const CliResult again =
        runUnit(sim.pty, example("recipe-dbu200.json"), QStringLiteral("SN-L"), db, line);
    EXPECT_EQ(again.code, 0) << (again.out + again.err).toStdString();
    const auto third = recordOf(db, QStringLiteral("SN-L"));
    ASSERT_TRUE(third);
    EXPECT_FALSE(third->drives.value(0).variantProof.contains(QStringLiteral("set back")));
}
