// `opentop-cli eol run --serial` end to end (issue 28, item 5): the real program on a
// pseudo-terminal against opentop-sim. A serial carrying a terminal escape is refused with exit 3
// and nothing recorded or sent, whatever the recipe; a serial that does not match the recipe's
// serialPattern is refused naming the pattern; a matching serial is tested and recorded as given.
#include "model/eol/RecipeFile.h"
#include "model/eol/ResultDatabase.h"
#include "model/eol/ResultQueries.h"
#include "tests/e2e/CliProcess.h"
#include "tests/e2e/SimProcess.h"

#include <QFile>
#include <QTemporaryDir>

using namespace opentop;
using namespace opentop::test;

namespace {

constexpr int kCurrentSpeed = 0x0109; // DBU status.current_speed (fc 04)

class EolSerialE2e : public ::testing::Test
{
protected:
    void SetUp() override
    {
        QString error;
        ASSERT_TRUE(sim.start({QStringLiteral("--devices"), QStringLiteral("dbu200@1")}, &error))
            << error.toStdString();
        ASSERT_TRUE(dir.isValid());
        db = dir.filePath(QStringLiteral("results.db"));
    }

    // The example DBU200 recipe with a one-second hold and the serial pattern `pattern` ("" for
    // none).
    QString writeRecipe(const QString& pattern, const QString& example = QString())
    {
        QString error;
        std::optional<Recipe> recipe = RecipeFile::load(
            QStringLiteral(OPENTOP_SOURCE_DIR "/docs/examples/recipe-dbu200.json"), &error);
        EXPECT_TRUE(recipe) << error.toStdString();
        if (!recipe)
            return QString();
        for (RecipeStep& step : recipe->positions[0].steps)
            if (step.type == RecipeStep::Type::Hold)
                step.duration = 1;
        recipe->serialPattern = pattern;
        recipe->serialExample = example;
        const QString path = dir.filePath(pattern.isEmpty() ? QStringLiteral("any.json")
                                                            : QStringLiteral("c200.json"));
        EXPECT_TRUE(RecipeFile::save(*recipe, path, &error)) << error.toStdString();
        return path;
    }

    CliResult run(const QString& recipe, const QString& serial)
    {
        QProcess process;
        process.start(cliProgram(),
                      {QStringLiteral("--port"), sim.pty, QStringLiteral("eol"),
                       QStringLiteral("run"), recipe, QStringLiteral("--serial"), serial,
                       QStringLiteral("--db"), db, QStringLiteral("--station"),
                       QStringLiteral("e2e"), QStringLiteral("--value"),
                       QStringLiteral("1:spno3.speed=1500")});
        if (!process.waitForStarted(5000))
            return CliResult{-1, QString(), QStringLiteral("<cannot start opentop-cli>")};
        return finishCli(process, 60000);
    }

    // Every record the results database holds of `serial`; none when there is no database.
    int recordsOf(const QString& serial)
    {
        if (!QFile::exists(db))
            return 0;
        QString error;
        const std::unique_ptr<ResultDatabase> database = ResultDatabase::open(db, &error);
        EXPECT_TRUE(database) << error.toStdString();
        if (!database)
            return -1;
        const auto history = ResultQueries(*database).history(serial, &error);
        EXPECT_TRUE(history) << error.toStdString();
        return history ? int(history->size()) : -1;
    }

    SimProcess sim;
    QTemporaryDir dir;
    QString db;
};

} // namespace

TEST_F(EolSerialE2e, ASerialWithATerminalEscapeIsRefusedAndNothingIsRecordedOrSent)
{
    // $'SN\e]0;owned\a': retitles the terminal of whoever reads the output or the records.
    const QString hostile = QStringLiteral("SN\x1b]0;owned\a");
    const CliResult r = run(writeRecipe(QString()), hostile);
    EXPECT_EQ(r.code, 3) << (r.out + r.err).toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("--serial: a serial number may not hold control "
                                              "characters")) &&
                r.err.contains(QStringLiteral("U+001B")) &&
                r.err.contains(QStringLiteral("nothing was sent")))
        << r.err.toStdString();
    EXPECT_FALSE(r.out.contains(QChar(0x1b)) || r.err.contains(QChar(0x1b)))
        << "the escape reached the terminal";
    EXPECT_FALSE(QFile::exists(db)) << "the results database was opened for a refused serial";
    EXPECT_EQ(recordsOf(hostile), 0);
    EXPECT_EQ(sim.get(1, kCurrentSpeed, 4), 0);

    // White space at an end is refused too, not trimmed into another serial.
    const CliResult padded = run(writeRecipe(QString()), QStringLiteral("SN-1001 "));
    EXPECT_EQ(padded.code, 3) << (padded.out + padded.err).toStdString();
    EXPECT_TRUE(padded.err.contains(QStringLiteral("begins or ends with white space")))
        << padded.err.toStdString();
    EXPECT_FALSE(QFile::exists(db));
}

TEST_F(EolSerialE2e, OnlySerialsMatchingTheRecipesPatternAreTested)
{
    const QString recipe =
        writeRecipe(QStringLiteral("^C200-[0-9]{4}$"), QStringLiteral("C200-0001"));
    CliResult r = run(recipe, QStringLiteral("SN-1001"));
    EXPECT_EQ(r.code, 3) << (r.out + r.err).toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral(
        "serial number \"SN-1001\" does not match the recipe's serial pattern ^C200-[0-9]{4}$ "
        "(e.g. C200-0001); nothing was sent")))
        << r.err.toStdString();
    EXPECT_FALSE(QFile::exists(db));
    // Containing a match is not matching: the whole serial must.
    r = run(recipe, QStringLiteral("C200-00421"));
    EXPECT_EQ(r.code, 3) << (r.out + r.err).toStdString();
    EXPECT_FALSE(QFile::exists(db));

    r = run(recipe, QStringLiteral("C200-0042"));
    ASSERT_EQ(r.code, 0) << (r.out + r.err).toStdString();
    EXPECT_EQ(recordsOf(QStringLiteral("C200-0042")), 1);
    EXPECT_EQ(recordsOf(QStringLiteral("SN-1001")), 0);
    EXPECT_EQ(recordsOf(QStringLiteral("C200-00421")), 0);
    EXPECT_EQ(sim.get(1, kCurrentSpeed, 4), 0);
}
