// Recipe files: the examples load and pass the checker, a recipe reads back as it was written,
// the checksum refuses a changed file, and every kind of malformed file is refused with a
// reason naming the entry.
#include "model/files/BackupFile.h"
#include "tests/model/eol/RecipeTestSupport.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <algorithm>

using namespace opentop;
using namespace opentop::test;

namespace {

QJsonObject documentOf(const Recipe& recipe)
{
    return QJsonDocument::fromJson(RecipeFile::toJson(recipe)).object();
}

// The document with a correct checksum for whatever it now holds.
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

// Sets key `key` of step `step` of position `position` to `value`.
QJsonObject withStepValue(QJsonObject document, int position, int step, const QString& key,
                          const QJsonValue& value)
{
    QJsonArray positions = document.value(QStringLiteral("positions")).toArray();
    QJsonObject p = positions.at(position).toObject();
    QJsonArray steps = p.value(QStringLiteral("steps")).toArray();
    QJsonObject s = steps.at(step).toObject();
    s.insert(key, value);
    steps[step] = s;
    p.insert(QStringLiteral("steps"), steps);
    positions[position] = p;
    document.insert(QStringLiteral("positions"), positions);
    return document;
}

TEST(RecipeFile, ExamplesLoadAndPassTheChecker)
{
    for (const char* name : {"recipe-dbu200.json", "recipe-eight-dbu.json", "recipe-dcpid.json"}) {
        QString error;
        const std::optional<Recipe> recipe = RecipeFile::load(exampleRecipePath(name), &error);
        ASSERT_TRUE(recipe) << name << ": " << qPrintable(error);
        EXPECT_TRUE(problemsOf(*recipe).isEmpty()) << name << ":\n"
                                                   << qPrintable(textOf(problemsOf(*recipe)));
    }
    const Recipe eight = exampleRecipe("recipe-eight-dbu.json");
    ASSERT_EQ(eight.positions.size(), 8);
    for (int n = 1; n <= 8; ++n)
        EXPECT_NE(eight.position(n), nullptr) << n;
}

TEST(RecipeFile, RoundTripKeepsEverything)
{
    for (const char* name : {"recipe-dbu200.json", "recipe-eight-dbu.json", "recipe-dcpid.json"}) {
        const Recipe recipe = exampleRecipe(name);
        QString error;
        QString checksum;
        const std::optional<Recipe> again =
            RecipeFile::fromJson(RecipeFile::toJson(recipe), &error, &checksum);
        ASSERT_TRUE(again) << qPrintable(error);
        EXPECT_EQ(RecipeFile::toObject(*again), RecipeFile::toObject(recipe)) << name;
        EXPECT_EQ(checksum, RecipeFile::checksumOf(recipe));
        // and the file on disk is exactly what was read: its checksum is the recipe's
        QFile file(exampleRecipePath(name));
        ASSERT_TRUE(file.open(QIODevice::ReadOnly));
        const QByteArray text = file.readAll();
        const QJsonObject onDisk = QJsonDocument::fromJson(text).object();
        EXPECT_EQ(onDisk.value(QStringLiteral("checksum")).toString(), checksum) << name;
        // the examples are laid out as OpenTOP writes them
        EXPECT_EQ(RecipeFile::toJson(recipe), text) << name;
    }
    // a few fields by value, so that a reader that drops them fails here
    const Recipe dc = exampleRecipe("recipe-dcpid.json");
    ASSERT_EQ(dc.positions.size(), 1);
    const RecipePosition& p = dc.positions.first();
    EXPECT_EQ(p.machineNumber, 7);
    EXPECT_EQ(p.firmware, QStringList{QStringLiteral("1.0")});
    ASSERT_EQ(p.unitValues.size(), 1);
    EXPECT_EQ(p.unitValues.first().source, RecipeUnitValue::Source::Operator);
    EXPECT_DOUBLE_EQ(p.unitValues.first().max, 1.5);
    ASSERT_GE(p.steps.size(), 4);
    EXPECT_EQ(p.steps.at(3).type, RecipeStep::Type::Stop);
    EXPECT_EQ(p.steps.at(3).deceleration, std::optional<double>(0));
    EXPECT_DOUBLE_EQ(p.steps.at(3).margin, 1.5);
    const RecipeLimit& current = p.steps.at(2).limits.at(3);
    EXPECT_EQ(current.parameter, QStringLiteral("status.current"));
    EXPECT_EQ(current.statistic, QStringLiteral("max"));
    EXPECT_FALSE(current.lower);
    EXPECT_EQ(current.upper, std::optional<double>(3));
    EXPECT_EQ(current.unit, QStringLiteral("A"));
}

TEST(RecipeFile, IsWrittenForPeopleToRead)
{
    const QByteArray text = RecipeFile::toJson(exampleRecipe("recipe-dbu200.json"));
    const QList<QByteArray> lines = text.split('\n');
    auto has = [&](const char* line) {
        return std::any_of(lines.begin(), lines.end(),
                           [&](const QByteArray& l) { return l.trimmed() == line; });
    };
    // the product first, one setting, limit and simple step per line, the checksum last
    EXPECT_EQ(lines.value(1).trimmed(), QByteArray(R"("format": "opentop-recipe",)"));
    EXPECT_TRUE(has(R"("product": "Conveyor C-200",)")) << text.constData();
    EXPECT_TRUE(has(R"({"name": "spno2.speed", "value": 1500, "unit": "r/min"},)"))
        << text.constData();
    EXPECT_TRUE(has(R"({"type": "start", "direction": "cw"},)")) << text.constData();
    EXPECT_TRUE(
        has(R"({"parameter": "status.load", "statistic": "max", "upper": 80, "unit": "%"})"))
        << text.constData();
    EXPECT_TRUE(lines.value(lines.size() - 3).trimmed().startsWith("\"checksum\": \"sha256:"))
        << text.constData();
}

TEST(RecipeFile, ChecksumIsTheBackupFilesOverTheCanonicalCompactJson)
{
    const Recipe recipe = exampleRecipe("recipe-dbu200.json");
    QJsonObject document = documentOf(recipe);
    const QString given = document.take(QStringLiteral("checksum")).toString();
    const QByteArray canonical = QJsonDocument(document).toJson(QJsonDocument::Compact);
    EXPECT_EQ(given,
              QStringLiteral("sha256:") +
                  QString::fromLatin1(
                      QCryptographicHash::hash(canonical, QCryptographicHash::Sha256).toHex()));
}

TEST(RecipeFile, RefusesAFileChangedAfterItWasWritten)
{
    const QJsonObject document = documentOf(exampleRecipe("recipe-dbu200.json"));
    const QJsonObject tampered = withStepValue(document, 0, 3, QStringLiteral("tolerance"), 500);
    EXPECT_TRUE(refusal(QJsonDocument(tampered).toJson()).contains(QStringLiteral("checksum")));
    QJsonObject unsigned_ = document;
    unsigned_.remove(QStringLiteral("checksum"));
    EXPECT_TRUE(refusal(QJsonDocument(unsigned_).toJson()).contains(QStringLiteral("checksum")));
    // re-signed, the same change is read (and it is the checker's turn to judge it)
    QString error;
    const std::optional<Recipe> again = RecipeFile::fromJson(resigned(tampered), &error);
    ASSERT_TRUE(again) << qPrintable(error);
    EXPECT_DOUBLE_EQ(again->positions.first().steps.at(3).tolerance, 500);
}

TEST(RecipeFile, RefusesWhatIsNotARecipe)
{
    EXPECT_TRUE(refusal("{").contains(QStringLiteral("not a JSON file")));
    EXPECT_TRUE(refusal("[1]").contains(QStringLiteral("not an object")));
    EXPECT_TRUE(
        refusal(R"({"format": "opentop-backup"})").contains(QStringLiteral("opentop-backup")));
    QJsonObject document = documentOf(exampleRecipe("recipe-dbu200.json"));
    document.insert(QStringLiteral("formatVersion"), 2);
    EXPECT_TRUE(refusal(resigned(document)).contains(QStringLiteral("newer")));
    // Found by FuzzRecipeFile: a version beyond 64 bits was converted to an integer (undefined
    // behaviour, stopped by UBSan in the sanitizer run).
    document.insert(QStringLiteral("formatVersion"), 1.11111e115);
    const QString huge = refusal(resigned(document));
    EXPECT_TRUE(huge.contains(QStringLiteral("1.11111e+115"))) << qPrintable(huge);
    document.insert(QStringLiteral("formatVersion"), QStringLiteral("1"));
    EXPECT_TRUE(refusal(resigned(document)).contains(QStringLiteral("formatVersion")));
}

TEST(RecipeFile, WrongTypesAndUnknownKeysAreRefusedNamingTheEntry)
{
    const QJsonObject document = documentOf(exampleRecipe("recipe-dbu200.json"));
    struct Case
    {
        int step;
        const char* key;
        QJsonValue value;
        const char* expected;
    };
    const Case cases[] = {
        {3, "timeout", QStringLiteral("5"),
         "positions[0] (position 1 (machine number 1)) "
         "steps[3] (wait for speed): \"timeout\" must be a number"},
        {3, "tolrance", 5, "unknown key \"tolrance\""},
        {1, "spno", 2.5, "\"spno\" must be a running data number"},
        {2, "direction", QStringLiteral("left"), "\"direction\" must be \"cw\" or \"ccw\""},
        {0, "type", QStringLiteral("jump"), "steps[0]: unknown step type \"jump\""},
        {4, "limits",
         QJsonArray{QJsonObject{{QStringLiteral("parameter"), QStringLiteral("status.load")},
                                {QStringLiteral("statistic"), QStringLiteral("max")},
                                {QStringLiteral("unit"), QStringLiteral("%")}}},
         "limits[0]: a limit needs \"lower\", \"upper\" or both"},
    };
    for (const Case& c : cases) {
        const QString error = refusal(
            resigned(withStepValue(document, 0, c.step, QString::fromLatin1(c.key), c.value)));
        EXPECT_TRUE(error.contains(QString::fromUtf8(c.expected))) << qPrintable(error);
    }
    QJsonObject bad = document;
    QJsonArray positions = bad.value(QStringLiteral("positions")).toArray();
    QJsonObject p = positions.at(0).toObject();
    p.insert(QStringLiteral("machineNumber"), 248);
    positions[0] = p;
    bad.insert(QStringLiteral("positions"), positions);
    EXPECT_TRUE(refusal(resigned(bad))
                    .contains(QStringLiteral("positions[0]: \"machineNumber\" "
                                             "must be a machine number 1–247")));
    p.insert(QStringLiteral("machineNumber"), 1);
    p.insert(QStringLiteral("settings"), QJsonArray{QJsonObject{{QStringLiteral("name"), 5}}});
    positions[0] = p;
    bad.insert(QStringLiteral("positions"), positions);
    EXPECT_TRUE(refusal(resigned(bad)).contains(QStringLiteral("settings[0]: \"name\" must be")));
    bad.insert(QStringLiteral("positions"), QJsonArray());
    EXPECT_TRUE(refusal(resigned(bad)).contains(QStringLiteral("names no drive")));
    QJsonArray many;
    for (int i = 0; i < 1001; ++i)
        many << QJsonObject();
    bad.insert(QStringLiteral("positions"), many);
    EXPECT_TRUE(refusal(resigned(bad)).contains(QStringLiteral("at most 1000 are allowed")));
    bad = document;
    bad.insert(QStringLiteral("tool"), QStringLiteral("x"));
    EXPECT_TRUE(
        refusal(resigned(bad)).contains(QStringLiteral("the recipe: unknown key \"tool\"")));
}

TEST(RecipeFile, SavesAtomicallyAndRefusesOversizedFiles)
{
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const Recipe recipe = exampleRecipe("recipe-dcpid.json");
    const QString path = dir.filePath(QStringLiteral("lift.json"));
    QString error;
    ASSERT_TRUE(RecipeFile::save(recipe, path, &error)) << qPrintable(error);
    QString checksum;
    const std::optional<Recipe> loaded = RecipeFile::load(path, &error, &checksum);
    ASSERT_TRUE(loaded) << qPrintable(error);
    EXPECT_EQ(RecipeFile::toObject(*loaded), RecipeFile::toObject(recipe));
    EXPECT_EQ(checksum, RecipeFile::checksumOf(recipe));
    EXPECT_TRUE(QDir(dir.path()).entryList(QDir::Files) == QStringList{QStringLiteral("lift.json")})
        << "no temporary file left";

    const QString big = dir.filePath(QStringLiteral("big.json"));
    QFile file(big);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(QByteArray(RecipeFile::kMaxFileBytes + 1, ' '));
    file.close();
    EXPECT_FALSE(RecipeFile::load(big, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("larger than"))) << qPrintable(error);
    EXPECT_FALSE(RecipeFile::load(dir.filePath(QStringLiteral("missing.json")), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("cannot read"))) << qPrintable(error);
}

} // namespace
