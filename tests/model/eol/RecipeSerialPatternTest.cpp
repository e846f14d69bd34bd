// A recipe's serial-number pattern in its file (issue 28, item 5): "serialPattern" and
// "serialExample" are read and written back, covered by the checksum like every other field,
// left out when empty so that a recipe signed before they existed keeps its checksum, and a
// pattern that is no regular expression (or an example it refuses) is refused naming the field.
#include "model/files/BackupFile.h"
#include "tests/model/eol/RecipeTestSupport.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>

using namespace opentop;
using namespace opentop::test;

namespace {

const QString kPattern = QStringLiteral("^C200-[0-9]{4}$");
const QString kExample = QStringLiteral("C200-0001");

QJsonObject documentOf(const Recipe& recipe)
{
    return QJsonDocument::fromJson(RecipeFile::toJson(recipe)).object();
}

QByteArray resigned(QJsonObject document)
{
    document.remove(QStringLiteral("checksum"));
    document.insert(QStringLiteral("checksum"), BackupFile::checksumOf(document));
    return QJsonDocument(document).toJson();
}

QString refusal(const QByteArray& data)
{
    QString error;
    EXPECT_FALSE(RecipeFile::fromJson(data, &error)) << "accepted";
    EXPECT_FALSE(error.isEmpty());
    return error;
}

Recipe withPattern()
{
    Recipe recipe = exampleRecipe("recipe-dbu200.json");
    recipe.serialPattern = kPattern;
    recipe.serialExample = kExample;
    return recipe;
}

} // namespace

TEST(RecipeSerialPattern, IsWrittenAfterTheDescriptionAndReadBack)
{
    const Recipe recipe = withPattern();
    const QByteArray text = RecipeFile::toJson(recipe);
    const QList<QByteArray> lines = text.split('\n');
    int at = -1;
    for (int i = 0; i < lines.size(); ++i)
        if (lines.at(i).trimmed() == R"("serialPattern": "^C200-[0-9]{4}$",)")
            at = i;
    ASSERT_GE(at, 0) << text.constData();
    EXPECT_EQ(lines.value(at + 1).trimmed(), QByteArray(R"("serialExample": "C200-0001",)"))
        << text.constData();
    EXPECT_TRUE(lines.value(at - 1).trimmed().startsWith("\"description\":")) << text.constData();

    QString error;
    QString checksum;
    const std::optional<Recipe> again = RecipeFile::fromJson(text, &error, &checksum);
    ASSERT_TRUE(again) << qPrintable(error);
    EXPECT_EQ(again->serialPattern, kPattern);
    EXPECT_EQ(again->serialExample, kExample);
    EXPECT_EQ(checksum, RecipeFile::checksumOf(recipe));
    EXPECT_EQ(RecipeFile::toJson(*again), text);
    EXPECT_TRUE(problemsOf(*again).isEmpty()) << qPrintable(textOf(problemsOf(*again)));
}

TEST(RecipeSerialPattern, ARecipeWithoutOneKeepsTheChecksumItWasSignedWith)
{
    // The example was signed before the fields existed: read, it verifies; written again, it is
    // the same file, so an approval of its checksum still holds.
    QFile file(exampleRecipePath("recipe-dbu200.json"));
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QByteArray onDisk = file.readAll();
    QString error;
    QString checksum;
    const std::optional<Recipe> recipe = RecipeFile::fromJson(onDisk, &error, &checksum);
    ASSERT_TRUE(recipe) << qPrintable(error);
    EXPECT_TRUE(recipe->serialPattern.isEmpty());
    EXPECT_EQ(
        checksum,
        QJsonDocument::fromJson(onDisk).object().value(QStringLiteral("checksum")).toString());
    EXPECT_EQ(RecipeFile::checksumOf(*recipe), checksum);
    EXPECT_FALSE(RecipeFile::toObject(*recipe).contains(QStringLiteral("serialPattern")));
    EXPECT_FALSE(RecipeFile::toObject(*recipe).contains(QStringLiteral("serialExample")));

    // The pattern is part of what the checksum covers: another recipe version.
    EXPECT_NE(RecipeFile::checksumOf(withPattern()), checksum);
    Recipe otherExample = withPattern();
    otherExample.serialExample = QStringLiteral("C200-0002");
    EXPECT_NE(RecipeFile::checksumOf(otherExample), RecipeFile::checksumOf(withPattern()));
}

TEST(RecipeSerialPattern, APatternAddedOrChangedByHandIsRefusedUntilSigned)
{
    QJsonObject document = documentOf(exampleRecipe("recipe-dbu200.json"));
    document.insert(QStringLiteral("serialPattern"), QStringLiteral(".*"));
    EXPECT_TRUE(refusal(QJsonDocument(document).toJson()).contains(QStringLiteral("checksum")));

    QJsonObject loosened = documentOf(withPattern());
    loosened.insert(QStringLiteral("serialPattern"), QStringLiteral(".*"));
    EXPECT_TRUE(refusal(QJsonDocument(loosened).toJson()).contains(QStringLiteral("checksum")));
    QJsonObject dropped = documentOf(withPattern());
    dropped.remove(QStringLiteral("serialPattern"));
    dropped.remove(QStringLiteral("serialExample"));
    EXPECT_TRUE(refusal(QJsonDocument(dropped).toJson()).contains(QStringLiteral("checksum")));
}

TEST(RecipeSerialPattern, ABadPatternOrExampleIsRefusedNamingTheField)
{
    const QJsonObject document = documentOf(withPattern());
    struct Case
    {
        const char* key;
        QJsonValue value;
        const char* expected;
    };
    const Case cases[] = {
        {"serialPattern", QStringLiteral("^C200-[0-9{4}$"),
         "\"serialPattern\" ^C200-[0-9{4}$ is not a valid regular expression: "},
        {"serialPattern", QStringLiteral("(C200"), "\"serialPattern\" (C200 is not a valid"},
        {"serialPattern", QStringLiteral(""), "\"serialPattern\" must be a non-empty text"},
        {"serialPattern", 5, "\"serialPattern\" must be a non-empty text"},
        {"serialPattern", QStringLiteral("C200\x1b"), "\"serialPattern\" may not hold control"},
        {"serialExample", QStringLiteral("C200-1"),
         "\"serialExample\": serial number \"C200-1\" does not match the recipe's serial pattern "
         "^C200-[0-9]{4}$"},
        {"serialExample", QStringLiteral("C200-0001 "), "\"serialExample\": serial number"},
        {"serial_pattern", QStringLiteral("^C200$"), "the recipe: unknown key \"serial_pattern\""},
    };
    for (const Case& c : cases) {
        QJsonObject bad = document;
        bad.insert(QString::fromLatin1(c.key), c.value);
        const QString error = refusal(resigned(bad));
        EXPECT_TRUE(error.contains(QString::fromUtf8(c.expected)))
            << c.key << ": " << qPrintable(error);
    }
    QJsonObject exampleAlone = documentOf(exampleRecipe("recipe-dbu200.json"));
    exampleAlone.insert(QStringLiteral("serialExample"), kExample);
    EXPECT_TRUE(
        refusal(resigned(exampleAlone)).contains(QStringLiteral("needs a \"serialPattern\"")));
}

TEST(RecipeSerialPattern, TheCheckerRefusesABadPatternOfARecipeMadeInTheProgram)
{
    Recipe recipe = withPattern();
    recipe.serialPattern = QStringLiteral("C200-[");
    QVector<RecipeProblem> problems = problemsOf(recipe);
    ASSERT_EQ(problems.size(), 1) << qPrintable(textOf(problems));
    EXPECT_EQ(problems.first().path, QStringLiteral("serialPattern"));
    EXPECT_TRUE(problems.first().message.contains(QStringLiteral("not a valid regular expression")))
        << qPrintable(problems.first().message);

    recipe.serialPattern = kPattern;
    recipe.serialExample = QStringLiteral("X");
    problems = problemsOf(recipe);
    ASSERT_EQ(problems.size(), 1) << qPrintable(textOf(problems));
    EXPECT_EQ(problems.first().path, QStringLiteral("serialExample"));
}
