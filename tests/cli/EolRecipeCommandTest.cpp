// `opentop-cli eol recipe create|check|sign|show` as a user runs them: recipes made from a
// backup file and from drives on a simulated bus, refused recipes, a hand-edited recipe.
#include "cli/ExitCode.h"
#include "model/eol/RecipeFile.h"
#include "tests/cli/CliTestSupport.h"
#include "tests/support/FileSizeLimit.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

class EolRecipeCommand : public ::testing::Test
{
protected:
    void SetUp() override { ASSERT_TRUE(dir.isValid()); }

    QString path(const char* name) const { return dir.filePath(QString::fromLatin1(name)); }

    static QString example(const char* name)
    {
        return QStringLiteral(OPENTOP_SOURCE_DIR "/docs/examples/") + QString::fromLatin1(name);
    }

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

    // The example DBU200 recipe copied into the test's folder.
    QString exampleCopy()
    {
        const QString file = path("recipe.json");
        write(file, read(example("recipe-dbu200.json")));
        return file;
    }

    QTemporaryDir dir;
};

} // namespace

TEST_F(EolRecipeCommand, CreateFromBackupPassesCheckAndKeepsAnExistingFile)
{
    const QString backup = path("golden.json");
    CliRun r = runCli({QStringLiteral("backup"), QStringLiteral("1"), QStringLiteral("7"),
                       QStringLiteral("-o"), backup, QStringLiteral("--sim"),
                       QStringLiteral("dbu200@1,dcpid@7")});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    const QString recipe = path("c200.json");
    const QStringList create{QStringLiteral("eol"),
                             QStringLiteral("recipe"),
                             QStringLiteral("create"),
                             QStringLiteral("--from-backup"),
                             backup,
                             QStringLiteral("--product"),
                             QStringLiteral("Conveyor C-200"),
                             QStringLiteral("--revision"),
                             QStringLiteral("A"),
                             QStringLiteral("-o"),
                             recipe};
    r = runCli(create);
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_TRUE(r.out.contains(QStringLiteral("wrote %1: Conveyor C-200 revision A").arg(recipe)))
        << qPrintable(r.out);

    QString error;
    const std::optional<Recipe> made = RecipeFile::load(recipe, &error);
    ASSERT_TRUE(made) << qPrintable(error);
    ASSERT_EQ(made->positions.size(), 2);
    EXPECT_EQ(made->positions.at(0).machineNumber, 1);
    EXPECT_EQ(made->positions.at(0).variants, QStringList{QStringLiteral("dbu200")});
    EXPECT_EQ(made->positions.at(1).family, QStringLiteral("dcpid"));
    EXPECT_FALSE(made->positions.at(0).steps.isEmpty());

    r = runCli({QStringLiteral("eol"), QStringLiteral("recipe"), QStringLiteral("check"), recipe});
    EXPECT_EQ(r.code, ExitOk) << qPrintable(r.out + r.err);
    EXPECT_TRUE(r.out.startsWith(QStringLiteral("valid: Conveyor C-200 revision A: 2 position")))
        << qPrintable(r.out);

    // An existing recipe is kept unless --force says otherwise.
    write(recipe, "keep me");
    r = runCli(create);
    EXPECT_EQ(r.code, ExitUsage);
    EXPECT_TRUE(r.err.contains(QStringLiteral("--force"))) << qPrintable(r.err);
    EXPECT_EQ(read(recipe), QByteArray("keep me"));
    r = runCli(QStringList(create) << QStringLiteral("--force"));
    EXPECT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_TRUE(RecipeFile::load(recipe, &error)) << qPrintable(error);
}

TEST_F(EolRecipeCommand, CreateFromDrivesOnASimulatedBusPassesCheck)
{
    const QString recipe = path("two.json");
    CliRun r =
        runCli({QStringLiteral("eol"), QStringLiteral("recipe"), QStringLiteral("create"),
                QStringLiteral("--sim"), QStringLiteral("dbu200@1,dbu400@2"),
                QStringLiteral("--drives"), QStringLiteral("1,2"), QStringLiteral("--product"),
                QStringLiteral("Twin"), QStringLiteral("--revision"), QStringLiteral("3"),
                QStringLiteral("-o"), recipe, QStringLiteral("--json")});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    const QJsonObject json = QJsonDocument::fromJson(r.out.toUtf8()).object();
    EXPECT_TRUE(json.value(QStringLiteral("valid")).toBool()) << qPrintable(r.out);
    EXPECT_EQ(json.value(QStringLiteral("positions")).toInt(), 2);
    QString error;
    QString checksum;
    const std::optional<Recipe> made = RecipeFile::load(recipe, &error, &checksum);
    ASSERT_TRUE(made) << qPrintable(error);
    EXPECT_EQ(json.value(QStringLiteral("checksum")).toString(), checksum);
    ASSERT_EQ(made->positions.size(), 2);
    EXPECT_EQ(made->positions.at(1).machineNumber, 2);
    EXPECT_EQ(made->positions.at(1).variants, QStringList{QStringLiteral("dbu400")});

    r = runCli({QStringLiteral("eol"), QStringLiteral("recipe"), QStringLiteral("check"), recipe});
    EXPECT_EQ(r.code, ExitOk) << qPrintable(r.out + r.err);

    // A drive that is not there: nothing written.
    const QString missing = path("missing.json");
    r = runCli({QStringLiteral("eol"), QStringLiteral("recipe"), QStringLiteral("create"),
                QStringLiteral("--sim"), QStringLiteral("dbu200@1"), QStringLiteral("--drives"),
                QStringLiteral("1,9"), QStringLiteral("--product"), QStringLiteral("Twin"),
                QStringLiteral("--revision"), QStringLiteral("3"), QStringLiteral("-o"), missing,
                QStringLiteral("--timeout"), QStringLiteral("50"), QStringLiteral("--retries"),
                QStringLiteral("0")});
    EXPECT_EQ(r.code, ExitCommunication) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("machine number 9"))) << qPrintable(r.err);
    EXPECT_FALSE(QFile::exists(missing));
}

TEST_F(EolRecipeCommand, CheckOfABrokenRecipePrintsPathsAndExits3)
{
    QString error;
    std::optional<Recipe> recipe = RecipeFile::load(example("recipe-dbu200.json"), &error);
    ASSERT_TRUE(recipe) << qPrintable(error);
    RecipePosition& p = recipe->positions[0];
    for (RecipeSetting& s : p.settings) {
        if (s.name == QLatin1String("spno2.accel"))
            s.value = 99;
    }
    p.settings << RecipeSetting{QStringLiteral("spno2.nonsense"), 1, QString()};
    const QString file = path("broken.json");
    ASSERT_TRUE(RecipeFile::save(*recipe, file, &error)) << qPrintable(error);

    CliRun r =
        runCli({QStringLiteral("eol"), QStringLiteral("recipe"), QStringLiteral("check"), file});
    EXPECT_EQ(r.code, ExitInvalid);
    EXPECT_TRUE(r.out.contains(QStringLiteral("positions[0].settings[1].value: ")))
        << qPrintable(r.out);
    EXPECT_TRUE(r.out.contains(QStringLiteral("SPno2 acceleration time"))) << qPrintable(r.out);
    EXPECT_TRUE(r.out.contains(QStringLiteral("positions[0].settings[5]"))) << qPrintable(r.out);
    EXPECT_TRUE(r.out.contains(QStringLiteral("spno2.nonsense"))) << qPrintable(r.out);
    EXPECT_TRUE(r.err.contains(QStringLiteral("2 problem"))) << qPrintable(r.err);
    EXPECT_FALSE(r.out.contains(QStringLiteral("valid:")));

    r = runCli({QStringLiteral("eol"), QStringLiteral("recipe"), QStringLiteral("check"), file,
                QStringLiteral("--json")});
    EXPECT_EQ(r.code, ExitInvalid);
    const QJsonObject json = QJsonDocument::fromJson(r.out.toUtf8()).object();
    EXPECT_FALSE(json.value(QStringLiteral("valid")).toBool());
    EXPECT_EQ(json.value(QStringLiteral("problems")).toArray().size(), 2) << qPrintable(r.out);

    // Not a recipe at all, and no file.
    write(path("junk.json"), "{\"format\": \"something else\"}");
    r = runCli({QStringLiteral("eol"), QStringLiteral("recipe"), QStringLiteral("check"),
                path("junk.json")});
    EXPECT_EQ(r.code, ExitInvalid);
    EXPECT_TRUE(r.err.contains(QStringLiteral("not an OpenTOP recipe file"))) << qPrintable(r.err);
    r = runCli({QStringLiteral("eol"), QStringLiteral("recipe"), QStringLiteral("check"),
                path("none.json")});
    EXPECT_EQ(r.code, ExitUsage);
    EXPECT_TRUE(r.err.contains(QStringLiteral("no such file"))) << qPrintable(r.err);
}

TEST_F(EolRecipeCommand, CheckWithUnitValuesFromACsvFile)
{
    const QString recipe = exampleCopy();
    write(path("units.csv"), "serial,spno3.speed\r\nC200-0001,1450\r\nC200-0002,1530\r\n");
    CliRun r = runCli({QStringLiteral("eol"), QStringLiteral("recipe"), QStringLiteral("check"),
                       recipe, QStringLiteral("--units"), path("units.csv")});
    EXPECT_EQ(r.code, ExitOk) << qPrintable(r.out + r.err);
    EXPECT_TRUE(r.out.contains(QStringLiteral("2 unit(s)"))) << qPrintable(r.out);

    write(path("bad.csv"), "serial,spno3.speed\nC200-0001,1450\nC200-0002,1700\n");
    r = runCli({QStringLiteral("eol"), QStringLiteral("recipe"), QStringLiteral("check"), recipe,
                QStringLiteral("--units"), path("bad.csv")});
    EXPECT_EQ(r.code, ExitInvalid);
    EXPECT_TRUE(r.out.contains(QStringLiteral("serial C200-0002"))) << qPrintable(r.out);
    EXPECT_FALSE(r.out.contains(QStringLiteral("serial C200-0001"))) << qPrintable(r.out);
}

TEST_F(EolRecipeCommand, AHandEditedRecipeIsRefusedUntilSigned)
{
    const QString recipe = exampleCopy();
    const QStringList check{QStringLiteral("eol"), QStringLiteral("recipe"),
                            QStringLiteral("check"), recipe};
    const QStringList sign{QStringLiteral("eol"), QStringLiteral("recipe"), QStringLiteral("sign"),
                           recipe};
    ASSERT_EQ(runCli(check).code, ExitOk);

    // A wrong value typed in by hand: refused, and signing refuses it too.
    QByteArray text = read(recipe);
    const QByteArray original = text;
    text.replace("\"value\": 2, \"unit\": \"s\"", "\"value\": 99, \"unit\": \"s\"");
    ASSERT_NE(text, original);
    write(recipe, text);
    CliRun r = runCli(check);
    EXPECT_EQ(r.code, ExitInvalid);
    EXPECT_TRUE(r.err.contains(QStringLiteral("opentop-cli eol recipe sign %1").arg(recipe)))
        << qPrintable(r.err);
    EXPECT_TRUE(r.out.contains(QStringLiteral("SPno2 acceleration time"))) << qPrintable(r.out);
    r = runCli(sign);
    EXPECT_EQ(r.code, ExitInvalid);
    EXPECT_TRUE(r.err.contains(QStringLiteral("not signed"))) << qPrintable(r.err);
    EXPECT_EQ(read(recipe), text);
    r = runCli({QStringLiteral("eol"), QStringLiteral("recipe"), QStringLiteral("show"), recipe});
    EXPECT_EQ(r.code, ExitInvalid);
    EXPECT_TRUE(r.err.contains(QStringLiteral("changed after OpenTOP wrote it")))
        << qPrintable(r.err);

    // A right value: refused until signed, then accepted.
    text = original;
    text.replace("\"value\": 2, \"unit\": \"s\"", "\"value\": 3, \"unit\": \"s\"");
    write(recipe, text);
    r = runCli(check);
    EXPECT_EQ(r.code, ExitInvalid);
    EXPECT_TRUE(r.out.isEmpty()) << qPrintable(r.out);
    EXPECT_TRUE(r.err.contains(QStringLiteral("eol recipe sign"))) << qPrintable(r.err);
    r = runCli(sign);
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_TRUE(r.out.startsWith(QStringLiteral("signed %1").arg(recipe))) << qPrintable(r.out);
    r = runCli(check);
    EXPECT_EQ(r.code, ExitOk) << qPrintable(r.out + r.err);
    QString error;
    const std::optional<Recipe> signedRecipe = RecipeFile::load(recipe, &error);
    ASSERT_TRUE(signedRecipe) << qPrintable(error);
    bool found = false;
    for (const RecipeSetting& s : signedRecipe->positions.at(0).settings) {
        if (s.name == QLatin1String("spno2.accel")) {
            EXPECT_EQ(s.value.toDouble(), 3.0);
            found = true;
        }
    }
    EXPECT_TRUE(found);
    // Signing an intact recipe changes nothing.
    const QByteArray signedText = read(recipe);
    r = runCli(sign);
    EXPECT_EQ(r.code, ExitOk);
    EXPECT_TRUE(r.out.contains(QStringLiteral("nothing changed"))) << qPrintable(r.out);
    EXPECT_EQ(read(recipe), signedText);
}

TEST_F(EolRecipeCommand, ShowListsLabelsWithUnitsAndStepsInWords)
{
    CliRun r = runCli({QStringLiteral("eol"), QStringLiteral("recipe"), QStringLiteral("show"),
                       example("recipe-dbu200.json")});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_TRUE(r.out.startsWith(QStringLiteral("Conveyor C-200, revision A")))
        << qPrintable(r.out);
    EXPECT_TRUE(r.out.contains(QStringLiteral("DBU200-D  1.5"))) << qPrintable(r.out);
    const QStringList lines = r.out.split(QLatin1Char('\n'));
    auto line = [&](const QString& start) {
        for (const QString& l : lines) {
            if (l.trimmed().startsWith(start))
                return l.simplified();
        }
        return QString();
    };
    EXPECT_EQ(line(QStringLiteral("SPno2 speed")), QStringLiteral("SPno2 speed 1500 r/min"));
    EXPECT_EQ(line(QStringLiteral("SPno2 acceleration time")),
              QStringLiteral("SPno2 acceleration time 2 s"));
    EXPECT_EQ(line(QStringLiteral("Load rate warning level")),
              QStringLiteral("Load rate warning level 90 %"));
    EXPECT_EQ(line(QStringLiteral("SPno3 speed")),
              QStringLiteral("SPno3 speed 1400 … 1600 r/min CSV file by serial"));
    EXPECT_EQ(line(QStringLiteral("4.")),
              QStringLiteral("4. wait for speed: 1500 ± 50 r/min within 5 s"));
    EXPECT_EQ(line(QStringLiteral("'Current speed' mean")),
              QStringLiteral("'Current speed' mean: 1475 … 1525 r/min"));
    EXPECT_EQ(line(QStringLiteral("'Load rate' max")), QStringLiteral("'Load rate' max: ≤ 80 %"));
    EXPECT_FALSE(r.out.contains(QStringLiteral("spno2.speed"))) << qPrintable(r.out);

    r = runCli({QStringLiteral("eol"), QStringLiteral("recipe"), QStringLiteral("show"),
                example("recipe-dcpid.json"), QStringLiteral("--json")});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    const QJsonObject json = QJsonDocument::fromJson(r.out.toUtf8()).object();
    EXPECT_EQ(json.value(QStringLiteral("recipe")).toObject().value(QStringLiteral("product")),
              QStringLiteral("Lift L-1"));
    EXPECT_TRUE(
        json.value(QStringLiteral("checksum")).toString().startsWith(QStringLiteral("sha256:")));
    EXPECT_FALSE(json.value(QStringLiteral("labels"))
                     .toObject()
                     .value(QStringLiteral("config.stall_time"))
                     .toString()
                     .isEmpty())
        << qPrintable(r.out);
}

TEST_F(EolRecipeCommand, WrongArgumentsAreUsageErrorsNamingTheProblem)
{
    struct Case
    {
        QStringList args;
        const char* says;
    };
    const QString out = path("out.json");
    const QVector<Case> cases{
        {{QStringLiteral("eol")}, "name a subcommand"},
        {{QStringLiteral("eol"), QStringLiteral("recipe")}, "unknown subcommand"},
        {{QStringLiteral("eol"), QStringLiteral("run"), QStringLiteral("r.json")}, "--serial S"},
        {{QStringLiteral("eol"), QStringLiteral("rerun"), QStringLiteral("r.json")},
         "unknown subcommand \"eol rerun"},
        {{QStringLiteral("eol"), QStringLiteral("recipe"), QStringLiteral("check")},
         "name one recipe file"},
        {{QStringLiteral("eol"), QStringLiteral("recipe"), QStringLiteral("create"),
          QStringLiteral("--product"), QStringLiteral("P"), QStringLiteral("--revision"),
          QStringLiteral("1"), QStringLiteral("-o"), out},
         "--from-backup FILE or --drives LIST"},
        {{QStringLiteral("eol"), QStringLiteral("recipe"), QStringLiteral("create"),
          QStringLiteral("--from-backup"), QStringLiteral("b.json"), QStringLiteral("--revision"),
          QStringLiteral("1"), QStringLiteral("-o"), out},
         "--product NAME"},
        {{QStringLiteral("eol"), QStringLiteral("recipe"), QStringLiteral("create"),
          QStringLiteral("--drives"), QStringLiteral("1,300"), QStringLiteral("--product"),
          QStringLiteral("P"), QStringLiteral("--revision"), QStringLiteral("1"),
          QStringLiteral("-o"), out},
         "300"},
        {{QStringLiteral("eol"), QStringLiteral("recipe"), QStringLiteral("show"),
          QStringLiteral("x.json"), QStringLiteral("--units"), QStringLiteral("u.csv")},
         "--units is not an option of this subcommand"},
        {{QStringLiteral("eol"), QStringLiteral("recipe"), QStringLiteral("check"),
          QStringLiteral("x.json"), QStringLiteral("--yes")},
         "--yes is not an option"},
    };
    for (const Case& c : cases) {
        const CliRun r = runCli(c.args);
        EXPECT_EQ(r.code, ExitUsage) << qPrintable(c.args.join(QLatin1Char(' ')) + r.err);
        EXPECT_TRUE(r.err.contains(QString::fromUtf8(c.says)))
            << qPrintable(c.args.join(QLatin1Char(' ')) + QStringLiteral(": ") + r.err);
    }
    EXPECT_FALSE(QFile::exists(out));

    const CliRun help = runCli({QStringLiteral("help"), QStringLiteral("eol")});
    EXPECT_EQ(help.code, ExitOk);
    for (const char* sub :
         {"eol recipe create", "eol recipe check RECIPE [--units CSV]", "eol recipe sign RECIPE",
          "eol recipe show RECIPE", "eol results", "eol certificate SERIAL"})
        EXPECT_TRUE(help.out.contains(QString::fromLatin1(sub))) << sub << qPrintable(help.out);
    EXPECT_EQ(runCli({QStringLiteral("eol"), QStringLiteral("--help")}).out, help.out);
    EXPECT_TRUE(runCli({QStringLiteral("--help")}).out.contains(QStringLiteral("eol run|recipe|")));
}

// Signing on a full disk (issue 28): refused with the reason, and the recipe is not emptied.
TEST_F(EolRecipeCommand, SigningOnAFullDiskLeavesTheRecipeAsItWas)
{
    const QString recipe = exampleCopy();
    QByteArray text = read(recipe);
    text.replace("\"value\": 2, \"unit\": \"s\"", "\"value\": 3, \"unit\": \"s\"");
    write(recipe, text);
    CliRun r;
    {
        test::FileSizeLimit full(256);
        ASSERT_TRUE(full.ok());
        r = runCli(
            {QStringLiteral("eol"), QStringLiteral("recipe"), QStringLiteral("sign"), recipe});
    }
    EXPECT_NE(r.code, ExitOk) << qPrintable(r.out + r.err);
    EXPECT_FALSE(r.out.contains(QStringLiteral("signed"))) << qPrintable(r.out);
    EXPECT_TRUE(r.err.contains(QStringLiteral("cannot write %1").arg(recipe))) << qPrintable(r.err);
    EXPECT_EQ(read(recipe), text);
}
