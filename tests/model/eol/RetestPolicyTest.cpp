#include "model/eol/RetestPolicy.h"
#include "model/eol/RecipeFile.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

ResultQueries::SerialHistory history(int verdicts, int failures, bool passed)
{
    ResultQueries::SerialHistory h;
    h.verdicts = verdicts;
    h.failures = failures;
    h.passedAny = passed;
    return h;
}

using Kind = RetestPolicy::Decision::Kind;

} // namespace

TEST(RetestPolicyTest, AttemptsAreNumberedUntilTheLimitThenATechnicianDecides)
{
    RecipeRetest rules; // 3 attempts, a passed serial asks a technician
    const QString sn = QStringLiteral("SN-1");
    EXPECT_EQ(RetestPolicy::decide(rules, sn, history(0, 0, false)).kind, Kind::Allowed);
    EXPECT_EQ(RetestPolicy::decide(rules, sn, history(0, 0, false)).attempt, 1);
    EXPECT_EQ(RetestPolicy::decide(rules, sn, history(2, 2, false)).attempt, 3);
    EXPECT_EQ(RetestPolicy::decide(rules, sn, history(2, 2, false)).kind, Kind::Allowed);
    const auto used = RetestPolicy::decide(rules, sn, history(3, 3, false));
    EXPECT_EQ(used.kind, Kind::NeedsTechnician);
    EXPECT_TRUE(used.reason.contains(QStringLiteral("3 times"))) << qPrintable(used.reason);
    rules.maxAttempts = 0; // no limit
    EXPECT_EQ(RetestPolicy::decide(rules, sn, history(30, 30, false)).kind, Kind::Allowed);
}

TEST(RetestPolicyTest, APassedSerialFollowsTheRecipesRule)
{
    RecipeRetest rules;
    const QString sn = QStringLiteral("SN-2");
    const auto asked = RetestPolicy::decide(rules, sn, history(1, 0, true));
    EXPECT_EQ(asked.kind, Kind::NeedsTechnician);
    EXPECT_TRUE(asked.reason.contains(QStringLiteral("passed already")))
        << qPrintable(asked.reason);
    EXPECT_EQ(asked.attempt, 2);
    rules.passed = RecipeRetest::Passed::Refuse;
    EXPECT_EQ(RetestPolicy::decide(rules, sn, history(1, 0, true)).kind, Kind::Refused);
    rules.passed = RecipeRetest::Passed::Allow;
    EXPECT_EQ(RetestPolicy::decide(rules, sn, history(1, 0, true)).kind, Kind::Allowed);
}

TEST(RetestPolicyTest, TheRulesLiveInTheRecipeFileAndTheDefaultsKeepOldChecksums)
{
    QString error;
    std::optional<Recipe> recipe = RecipeFile::load(
        QStringLiteral(OPENTOP_SOURCE_DIR "/docs/examples/recipe-dbu200.json"), &error);
    ASSERT_TRUE(recipe) << qPrintable(error);
    EXPECT_EQ(recipe->retest, RecipeRetest());
    const QString before = RecipeFile::checksumOf(*recipe);
    EXPECT_FALSE(RecipeFile::toJson(*recipe).contains("retest")) << "defaults are not written";
    recipe->retest.maxAttempts = 5;
    recipe->retest.passed = RecipeRetest::Passed::Refuse;
    EXPECT_NE(RecipeFile::checksumOf(*recipe), before) << "the rules are part of the recipe";
    const auto again = RecipeFile::fromJson(RecipeFile::toJson(*recipe), &error);
    ASSERT_TRUE(again) << qPrintable(error);
    EXPECT_EQ(again->retest, recipe->retest);

    QJsonObject doc = QJsonDocument::fromJson(RecipeFile::toJson(*recipe)).object();
    doc.insert(QStringLiteral("retest"),
               QJsonObject{{QStringLiteral("maxAttempts"), 2.5},
                           {QStringLiteral("passedSerial"), QStringLiteral("technician")}});
    EXPECT_FALSE(RecipeFile::fromEdited(doc, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("maxAttempts"))) << qPrintable(error);
    doc.insert(QStringLiteral("retest"),
               QJsonObject{{QStringLiteral("passedSerial"), QStringLiteral("sometimes")}});
    EXPECT_FALSE(RecipeFile::fromEdited(doc, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("technician, refuse or allow"))) << qPrintable(error);
}
