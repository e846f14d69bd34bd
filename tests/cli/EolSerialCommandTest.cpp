// A recipe's serial-number pattern on the command line (issue 28, item 5): added by hand and
// signed, shown by `eol recipe show`, a broken one refused naming the field; `eol run --serial`
// refuses a serial with control characters, white space at an end or not matching the pattern
// with exit 3 before the results database is even opened.
#include "cli/ExitCode.h"
#include "model/eol/RecipeFile.h"
#include "tests/cli/CliTestSupport.h"

#include <QFile>
#include <QTemporaryDir>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

class EolSerialCommand : public ::testing::Test
{
protected:
    void SetUp() override { ASSERT_TRUE(dir.isValid()); }

    QString path(const char* name) const { return dir.filePath(QString::fromLatin1(name)); }

    static QByteArray read(const QString& file)
    {
        QFile f(file);
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    }

    static void write(const QString& file, const QByteArray& data)
    {
        QFile f(file);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write(data);
    }

    // The example DBU200 recipe with `fields` added by hand after its revision (not signed).
    QString editedExample(const QByteArray& fields)
    {
        QByteArray text =
            read(QStringLiteral(OPENTOP_SOURCE_DIR "/docs/examples/recipe-dbu200.json"));
        const QByteArray after = "\"revision\": \"A\",\n";
        EXPECT_TRUE(text.contains(after));
        text.replace(after, after + fields);
        const QString file = path("recipe.json");
        write(file, text);
        return file;
    }

    CliRun run(const QString& recipe, const QString& serial)
    {
        return runCli({QStringLiteral("eol"), QStringLiteral("run"), recipe,
                       QStringLiteral("--serial"), serial, QStringLiteral("--db"), db(),
                       QStringLiteral("--station"), QStringLiteral("cli-test"),
                       QStringLiteral("--value"), QStringLiteral("1:spno3.speed=1500")});
    }

    QString db() const { return path("results.db"); }

    QTemporaryDir dir;
};

} // namespace

TEST_F(EolSerialCommand, APatternAddedByHandIsSignedAndShown)
{
    const QString recipe = editedExample(
        "  \"serialPattern\": \"^C200-[0-9]{4}$\",\n  \"serialExample\": \"C200-0001\",\n");
    const QStringList show{QStringLiteral("eol"), QStringLiteral("recipe"), QStringLiteral("show"),
                           recipe};
    CliRun r = runCli(show);
    EXPECT_EQ(r.code, ExitInvalid) << "changed by hand: the checksum covers the pattern";
    r = runCli({QStringLiteral("eol"), QStringLiteral("recipe"), QStringLiteral("sign"), recipe});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    QString error;
    const std::optional<Recipe> signedRecipe = RecipeFile::load(recipe, &error);
    ASSERT_TRUE(signedRecipe) << qPrintable(error);
    EXPECT_EQ(signedRecipe->serialPattern, QStringLiteral("^C200-[0-9]{4}$"));
    EXPECT_EQ(signedRecipe->serialExample, QStringLiteral("C200-0001"));

    r = runCli(show);
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_TRUE(
        r.out.contains(QStringLiteral("\nserial numbers: ^C200-[0-9]{4}$ (e.g. C200-0001)\n")))
        << qPrintable(r.out);
    r = runCli({QStringLiteral("eol"), QStringLiteral("recipe"), QStringLiteral("show"),
                QStringLiteral(OPENTOP_SOURCE_DIR "/docs/examples/recipe-dbu200.json")});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_TRUE(r.out.contains(QStringLiteral("\nserial numbers: any, at most 64 characters\n")))
        << qPrintable(r.out);
}

TEST_F(EolSerialCommand, ABrokenPatternIsRefusedNamingTheFieldAndNotSigned)
{
    const QString recipe = editedExample("  \"serialPattern\": \"^C200-[0-9{4}$\",\n");
    const QByteArray before = read(recipe);
    CliRun r =
        runCli({QStringLiteral("eol"), QStringLiteral("recipe"), QStringLiteral("check"), recipe});
    EXPECT_EQ(r.code, ExitInvalid);
    EXPECT_TRUE(r.err.contains(QStringLiteral("\"serialPattern\" ^C200-[0-9{4}$ is not a valid "
                                              "regular expression")))
        << qPrintable(r.err);
    r = runCli({QStringLiteral("eol"), QStringLiteral("recipe"), QStringLiteral("sign"), recipe});
    EXPECT_EQ(r.code, ExitInvalid);
    EXPECT_EQ(read(recipe), before) << "not signed";
}

TEST_F(EolSerialCommand, EolRunRefusesABadSerialBeforeAnythingIsOpened)
{
    const QString plain = QStringLiteral(OPENTOP_SOURCE_DIR "/docs/examples/recipe-dbu200.json");
    // Whatever the recipe: a terminal escape (it would retitle the operator's terminal), a line
    // break, white space at an end.
    struct Case
    {
        QString serial;
        const char* says;
    };
    const Case cases[] = {
        {QStringLiteral("SN\x1b]0;owned\a"), "character 3 is U+001B"},
        {QStringLiteral("SN1\nPASS"), "character 4 is U+000A"},
        {QStringLiteral("SN1 "), "begins or ends with white space"},
        {QString(65, QLatin1Char('7')), "at most 64 characters"},
    };
    for (const Case& c : cases) {
        const CliRun r = run(plain, c.serial);
        EXPECT_EQ(r.code, ExitInvalid) << qPrintable(r.err);
        EXPECT_TRUE(r.err.contains(QStringLiteral("--serial: ")) &&
                    r.err.contains(QString::fromLatin1(c.says)) &&
                    r.err.contains(QStringLiteral("nothing was sent")))
            << qPrintable(r.err);
        EXPECT_FALSE(r.err.contains(QChar(0x1b)) || r.out.contains(QChar(0x1b)));
        EXPECT_FALSE(QFile::exists(db())) << "the results database was opened";
    }

    // The recipe's pattern, named with its example.
    const QString recipe = editedExample(
        "  \"serialPattern\": \"^C200-[0-9]{4}$\",\n  \"serialExample\": \"C200-0001\",\n");
    ASSERT_EQ(
        runCli({QStringLiteral("eol"), QStringLiteral("recipe"), QStringLiteral("sign"), recipe})
            .code,
        ExitOk);
    const CliRun r = run(recipe, QStringLiteral("SN-1001"));
    EXPECT_EQ(r.code, ExitInvalid) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral(
        "--serial: serial number \"SN-1001\" does not match the recipe's serial pattern "
        "^C200-[0-9]{4}$ (e.g. C200-0001); nothing was sent")))
        << qPrintable(r.err);
    EXPECT_FALSE(QFile::exists(db()));
}
