// RecipeFromDrives, the one "recipe from a golden unit on the bus" of the command line and the
// recipe editor: each drive's variant proven on the bus before its settings are read, the
// recipe naming how, and a variant that cannot be known (or is contradicted) making nothing.
#include "model/eol/RecipeFromDrives.h"
#include "tests/model/eol/RecipeTestSupport.h"
#include "tests/model/files/BackupTestSupport.h"

using namespace opentop;
using namespace opentop::test;

namespace {

class RecipeFromDrivesTest : public SimBusFixture
{
protected:
    RecipeFromDrives::Result make(const QVector<RecipeFromDrives::Golden>& golden)
    {
        RecipeFromDrives from(client.get(), ProfileRegistry::builtIn(),
                              [this](int slave, QString*) { return session(slave); });
        return await<RecipeFromDrives::Result>(
            [&](auto done) {
                from.start(golden, QStringLiteral("Twin"), QStringLiteral("A"),
                           QStringLiteral("lin"), done);
            },
            20000);
    }
};

} // namespace

TEST_F(RecipeFromDrivesTest, EachVariantIsProvenOnTheBusAndTheRecipeSaysHow)
{
    const RecipeFromDrives::Result r = make({{1, {}, {}}, {150, {}, {}}});
    ASSERT_TRUE(r.recipe) << qPrintable(r.problems.join(QLatin1Char('\n')));
    EXPECT_EQ(r.failure, RecipeFromDrives::Failure::None);
    ASSERT_EQ(r.recipe->positions.size(), 2);
    EXPECT_EQ(r.recipe->positions[0].variants, QStringList{QStringLiteral("dbu200")});
    EXPECT_EQ(r.recipe->positions[1].variants, QStringList{QStringLiteral("dbu400")});
    EXPECT_TRUE(r.recipe->description.contains(QStringLiteral("machine number 150: dbu400, probed")))
        << qPrintable(r.recipe->description);
    EXPECT_EQ(r.recipe->product, QStringLiteral("Twin"));
    EXPECT_TRUE(problemsOf(*r.recipe).isEmpty()) << qPrintable(textOf(problemsOf(*r.recipe)));
}

TEST_F(RecipeFromDrivesTest, AStatedVariantTheProbeContradictsMakesNothing)
{
    // The DBU400 at 150 said to be a DBU200: the probe refuses it, and no recipe is made.
    const RecipeFromDrives::Result r =
        make({{1, {}, {}}, {150, {}, QStringLiteral("dbu200")}, {7, {}, {}}});
    EXPECT_FALSE(r.recipe);
    EXPECT_EQ(r.failure, RecipeFromDrives::Failure::Invalid);
    EXPECT_EQ(r.unknownVariants, QVector<int>{150});
    ASSERT_FALSE(r.problems.isEmpty());
    EXPECT_TRUE(r.problems.first().contains(QStringLiteral("machine number 150")))
        << qPrintable(r.problems.first());
}
