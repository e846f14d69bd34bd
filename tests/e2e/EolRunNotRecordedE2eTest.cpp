// `opentop-cli eol run` whose results file cannot take the unit's verdict (issue 28, item 4): the
// real program on a pseudo-terminal against opentop-sim, with an SQLite results file, and the
// disk "full" from the unit's hold step on (the program may no longer grow any file, as
// RLIMIT_FSIZE does; the unit's running row is committed by then). The verdict line on standard
// output must say NOT RECORDED, never a bare PASS or FAIL a script would take for a result; the
// --json result says it too; the exit status is 1, as for a database that does not answer.
#include "model/eol/RecipeFile.h"
#include "model/eol/ResultDatabase.h"
#include "model/eol/ResultQueries.h"
#include "tests/e2e/CliProcess.h"
#include "tests/e2e/SimProcess.h"

#include <QElapsedTimer>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <csignal>
#include <sys/resource.h>

using namespace opentop;
using namespace opentop::test;

namespace {

const QByteArray kHoldStep = "hold and measure";

// The example DBU200 recipe at machine number `id`, holding for 2 s: long enough to fill the
// disk while the unit runs.
QString writeRecipe(const QTemporaryDir& dir, int id)
{
    QString error;
    std::optional<Recipe> recipe = RecipeFile::load(
        QStringLiteral(OPENTOP_SOURCE_DIR "/docs/examples/recipe-dbu200.json"), &error);
    EXPECT_TRUE(recipe) << error.toStdString();
    recipe->positions[0].machineNumber = id;
    for (RecipeStep& step : recipe->positions[0].steps)
        if (step.type == RecipeStep::Type::Hold)
            step.duration = 2;
    const QString path = dir.filePath(QStringLiteral("recipe-%1.json").arg(id));
    EXPECT_TRUE(RecipeFile::save(*recipe, path, &error)) << error.toStdString();
    return path;
}

QStringList runArgs(const QString& port, const QString& recipe, const QString& serial,
                    const QString& db, int id, bool json)
{
    QStringList args{QStringLiteral("--port"),
                     port,
                     QStringLiteral("eol"),
                     QStringLiteral("run"),
                     recipe,
                     QStringLiteral("--serial"),
                     serial,
                     QStringLiteral("--db"),
                     db,
                     QStringLiteral("--station"),
                     QStringLiteral("e2e"),
                     QStringLiteral("--value"),
                     QStringLiteral("%1:spno3.speed=1500").arg(id)};
    if (json)
        args << QStringLiteral("--json");
    return args;
}

// From now on the process may not grow any file: its writes past a file's end fail with EFBIG
// (SIGXFSZ is ignored in it), as on a full disk. Pipes are not limited: its output goes on.
bool fillDiskOf(pid_t pid)
{
    rlimit limit{};
    if (::prlimit(pid, RLIMIT_FSIZE, nullptr, &limit) != 0)
        return false;
    limit.rlim_cur = 0;
    return ::prlimit(pid, RLIMIT_FSIZE, &limit, nullptr) == 0;
}

// Runs `eol run` to its end. With `filled`, the disk is full for it from the unit's hold step
// on, and *filled says whether that happened.
CliResult runEol(const QStringList& args, bool* filled = nullptr)
{
    QProcess process;
    // Ignored in the test while the program starts, so ignored in the program (kept across
    // exec): a write past the limit then fails instead of ending the program.
    const auto handler = std::signal(SIGXFSZ, SIG_IGN);
    process.start(cliProgram(), args);
    const bool started = process.waitForStarted(5000);
    std::signal(SIGXFSZ, handler);
    if (!started)
        return CliResult{-1, QString(), QStringLiteral("<cannot start opentop-cli>")};
    QByteArray out;
    QByteArray err;
    QElapsedTimer timer;
    timer.start();
    // The phase lines are on standard error, or on standard output with --json.
    while (filled && !*filled && timer.elapsed() < 30000 &&
           process.state() != QProcess::NotRunning) {
        process.waitForReadyRead(100);
        out += process.readAllStandardOutput();
        err += process.readAllStandardError();
        if (out.contains(kHoldStep) || err.contains(kHoldStep))
            *filled = fillDiskOf(pid_t(process.processId()));
    }
    CliResult r;
    if (!process.waitForFinished(60000)) {
        process.kill();
        process.waitForFinished(2000);
        r.err = QStringLiteral("<timed out>");
        return r;
    }
    r.code = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    r.out = QString::fromUtf8(out + process.readAllStandardOutput());
    r.err = QString::fromUtf8(err + process.readAllStandardError());
    return r;
}

// The verdict line of `serial` on standard output ("SERIAL  VERDICT  RECIPE rev. R  T s").
QString verdictLine(const QString& out, const QString& serial)
{
    for (const QString& line : out.split(QLatin1Char('\n')))
        if (line.startsWith(serial + QStringLiteral("  ")))
            return line;
    return QString();
}

// The JSON result line of standard output.
QJsonObject resultEvent(const QString& out)
{
    QJsonObject found;
    for (const QString& line : out.split(QLatin1Char('\n'), Qt::SkipEmptyParts)) {
        const QJsonObject o = QJsonDocument::fromJson(line.toUtf8()).object();
        if (o.value(QStringLiteral("event")).toString() == QLatin1String("result"))
            found = o;
    }
    return found;
}

std::optional<UnitStatus> statusOf(const QString& db, const QString& serial)
{
    QString error;
    const std::unique_ptr<ResultDatabase> database = ResultDatabase::open(db, &error);
    EXPECT_TRUE(database) << error.toStdString();
    if (!database)
        return std::nullopt;
    EXPECT_EQ(database->integrityCheck(), QStringLiteral("ok"));
    const auto history = ResultQueries(*database).history(serial, &error);
    EXPECT_TRUE(history && history->size() == 1) << error.toStdString();
    if (!history || history->isEmpty())
        return std::nullopt;
    return history->last().status;
}

class EolRunNotRecordedE2e : public ::testing::Test
{
protected:
    void SetUp() override
    {
        QString error;
        ASSERT_TRUE(sim.start({QStringLiteral("--devices"), QStringLiteral("dbu200@1-2"),
                               QStringLiteral("--defect"), QStringLiteral("2:load=+60")},
                              &error))
            << error.toStdString();
        db = dir.filePath(QStringLiteral("results.db"));
    }

    SimProcess sim;
    QTemporaryDir dir;
    QString db;
};

} // namespace

TEST_F(EolRunNotRecordedE2e, APassTheResultsFileCannotTakeIsPrintedNotRecordedAndExitsOne)
{
    const QString recipe = writeRecipe(dir, 1);
    // A unit recorded as usual: the plain verdict, exit 0.
    CliResult r = runEol(runArgs(sim.pty, recipe, QStringLiteral("SN-OK"), db, 1, false));
    ASSERT_EQ(r.code, 0) << (r.out + r.err).toStdString();
    EXPECT_TRUE(verdictLine(r.out, QStringLiteral("SN-OK"))
                    .startsWith(QStringLiteral("SN-OK  PASS  Conveyor C-200 rev. ")))
        << r.out.toStdString();
    EXPECT_FALSE(r.out.contains(QStringLiteral("NOT RECORDED"))) << r.out.toStdString();

    // The disk fills while the next unit runs: it passes, and its verdict is not recorded.
    bool filled = false;
    r = runEol(runArgs(sim.pty, recipe, QStringLiteral("SN-NR"), db, 1, false), &filled);
    ASSERT_TRUE(filled) << "the unit never reached its hold step: " << r.err.toStdString();
    EXPECT_EQ(r.code, 1) << (r.out + r.err).toStdString();
    const QString line = verdictLine(r.out, QStringLiteral("SN-NR"));
    EXPECT_TRUE(line.startsWith(QStringLiteral("SN-NR  NOT RECORDED (PASS)  Conveyor C-200 rev. ")))
        << r.out.toStdString();
    EXPECT_FALSE(r.out.contains(
        QRegularExpression(QStringLiteral("^SN-NR  PASS"), QRegularExpression::MultilineOption)))
        << "a bare PASS on the verdict channel: " << r.out.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("the result was NOT recorded: ")))
        << r.err.toStdString();
    // Its begun row is all the database has: visibly not a pass.
    EXPECT_EQ(statusOf(db, QStringLiteral("SN-NR")), UnitStatus::Running);
    EXPECT_EQ(statusOf(db, QStringLiteral("SN-OK")), UnitStatus::Pass);
}

TEST_F(EolRunNotRecordedE2e, AFailTheResultsFileCannotTakeIsPrintedNotRecordedWithItsReason)
{
    bool filled = false;
    const CliResult r = runEol(
        runArgs(sim.pty, writeRecipe(dir, 2), QStringLiteral("SN-NF"), db, 2, false), &filled);
    ASSERT_TRUE(filled) << "the unit never reached its hold step: " << r.err.toStdString();
    // 1, as a database that does not answer; not 5, which says the FAIL is recorded.
    EXPECT_EQ(r.code, 1) << (r.out + r.err).toStdString();
    EXPECT_TRUE(verdictLine(r.out, QStringLiteral("SN-NF"))
                    .startsWith(QStringLiteral("SN-NF  NOT RECORDED (FAIL)  Conveyor C-200 rev. ")))
        << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("Load rate"))) << r.out.toStdString();
    EXPECT_EQ(statusOf(db, QStringLiteral("SN-NF")), UnitStatus::Running);
}

TEST_F(EolRunNotRecordedE2e, TheJsonResultOfAPassNotRecordedSaysSoAndWhy)
{
    bool filled = false;
    const CliResult r = runEol(
        runArgs(sim.pty, writeRecipe(dir, 1), QStringLiteral("SN-NJ"), db, 1, true), &filled);
    ASSERT_TRUE(filled) << "the unit never reached its hold step: " << r.out.toStdString();
    EXPECT_EQ(r.code, 1) << (r.out + r.err).toStdString();
    const QJsonObject result = resultEvent(r.out);
    EXPECT_EQ(result.value(QStringLiteral("status")).toString(), QStringLiteral("pass"))
        << r.out.toStdString();
    EXPECT_EQ(result.value(QStringLiteral("recorded")), QJsonValue(false)) << r.out.toStdString();
    EXPECT_EQ(result.value(QStringLiteral("spooled")), QJsonValue(false)) << r.out.toStdString();
    EXPECT_FALSE(result.value(QStringLiteral("recordError")).toString().isEmpty())
        << r.out.toStdString();
    EXPECT_EQ(statusOf(db, QStringLiteral("SN-NJ")), UnitStatus::Running);
}
