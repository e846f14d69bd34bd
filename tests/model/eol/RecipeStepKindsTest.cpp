// RecipeStepKinds is the only list of step types: every RecipeStep::Type has exactly one entry
// with a name, a title and its fields; the parser accepts exactly the keys the table gives and
// refuses any other; names round-trip through a recipe file.
#include "model/eol/RecipeStepKinds.h"
#include "model/eol/Recipe.h"
#include "model/eol/RecipeFile.h"
#include "tests/model/eol/RecipeTestSupport.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QSet>

using namespace opentop;
using namespace opentop::test;

TEST(RecipeStepKindsTest, EveryStepTypeHasOneEntryWithANameATitleAndItsFields)
{
    // Every enumerator, from the first to the last: a new type without an entry fails here.
    QSet<QString> names;
    for (int t = int(RecipeStep::Type::Priority); t <= int(RecipeStep::Type::Read); ++t) {
        const auto type = RecipeStep::Type(t);
        const RecipeStepKinds::Kind* kind = RecipeStepKinds::of(type);
        ASSERT_TRUE(kind) << "step type " << t << " has no entry in RecipeStepKinds";
        EXPECT_FALSE(QString::fromLatin1(kind->name).isEmpty());
        EXPECT_FALSE(RecipeStepKinds::title(type).isEmpty());
        EXPECT_FALSE(names.contains(QString::fromLatin1(kind->name))) << kind->name;
        names.insert(QString::fromLatin1(kind->name));
        EXPECT_TRUE(Recipe::stepTypeFromName(QString::fromLatin1(kind->name)) == type);
        EXPECT_EQ(Recipe::stepTitle(type), RecipeStepKinds::title(type));
        QSet<QString> keys;
        for (const RecipeStepKinds::Field& f : kind->fields) {
            EXPECT_FALSE(keys.contains(QString::fromLatin1(f.key))) << kind->name << f.key;
            keys.insert(QString::fromLatin1(f.key));
        }
    }
    EXPECT_EQ(RecipeStepKinds::all().size(), names.size());
    EXPECT_EQ(Recipe::stepTypeNames().size(), names.size());
}

TEST(RecipeStepKindsTest, TheParserTakesTheTablesKeysAndRefusesOthers)
{
    Recipe recipe = exampleRecipe("recipe-dbu200.json");
    QJsonObject doc = QJsonDocument::fromJson(RecipeFile::toJson(recipe)).object();
    doc.remove(QStringLiteral("checksum"));
    QString error;
    ASSERT_TRUE(RecipeFile::fromEdited(doc, &error)) << qPrintable(error);
    // Every step of the example holds only keys of its type's entry.
    QJsonArray positions = doc.value(QStringLiteral("positions")).toArray();
    QJsonObject position = positions.at(0).toObject();
    QJsonArray steps = position.value(QStringLiteral("steps")).toArray();
    for (const QJsonValue& v : steps) {
        const QJsonObject step = v.toObject();
        const auto type = Recipe::stepTypeFromName(step.value(QStringLiteral("type")).toString());
        ASSERT_TRUE(type);
        for (const QString& key : step.keys())
            EXPECT_TRUE(RecipeStepKinds::keys(*type).contains(key)) << qPrintable(key);
    }
    // A key the table does not give for that type is refused, naming it.
    QJsonObject start = steps.at(2).toObject();
    ASSERT_EQ(start.value(QStringLiteral("type")).toString(), QStringLiteral("start"));
    start.insert(QStringLiteral("margin"), 1);
    steps[2] = start;
    position.insert(QStringLiteral("steps"), steps);
    positions[0] = position;
    doc.insert(QStringLiteral("positions"), positions);
    EXPECT_FALSE(RecipeFile::fromEdited(doc, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("margin"))) << qPrintable(error);
}

// One description of a step for the editor's table and `eol recipe show`, also of a step being
// edited that is not complete yet.
TEST(RecipeStepKindsTest, ASummarySaysWhatTheStepDoesAlsoWhileItIsIncomplete)
{
    auto step = [](const char* json) { return QJsonDocument::fromJson(QByteArray(json)).object(); };
    EXPECT_EQ(RecipeStepKinds::line(step(R"({"type":"waitSpeed","target":1500,"tolerance":50,
                                            "unit":"r/min","timeout":5})")),
              QStringLiteral("wait for speed: 1500 ± 50 r/min within 5 s"));
    EXPECT_EQ(RecipeStepKinds::summary(step(R"({"type":"waitSpeed","tolerance":50,"timeout":5})")),
              QStringLiteral("the drive's target speed ± 50 within 5 s"));
    EXPECT_EQ(RecipeStepKinds::line(step(R"({"type":"priority"})")),
              QStringLiteral("take communication priority"));
    EXPECT_EQ(RecipeStepKinds::summary(step(R"({"type":"hold","duration":5,"limits":[{},{}]})")),
              QStringLiteral("for 5 s; limits: 2"));
    EXPECT_EQ(RecipeStepKinds::summary(step(R"({"type":"stop","margin":1})")),
              QStringLiteral("stopped within the deceleration time + 1 s"));
    // A read names its parameter by the profile's label; an unfinished one says so.
    const Profile* dbu = ProfileRegistry::builtIn().family(QStringLiteral("dbu"));
    EXPECT_EQ(RecipeStepKinds::summary(
                  step(R"({"type":"read","parameter":"status.load","upper":80,"unit":"%"})"), dbu),
              QStringLiteral("Load rate between any and 80 %"));
    EXPECT_EQ(RecipeStepKinds::summary(step(R"({"type":"read"})")),
              QStringLiteral("no value chosen to read yet"));
    // Text typed where a number belongs is shown as typed, for the checker to name.
    EXPECT_EQ(RecipeStepKinds::summary(step(R"({"type":"select","spno":"two"})")),
              QStringLiteral("SPnotwo"));
    EXPECT_TRUE(RecipeStepKinds::summary(step(R"({"type":"nonsense"})")).isEmpty());
}
