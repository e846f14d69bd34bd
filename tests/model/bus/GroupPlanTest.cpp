// The order in which planned communication groups are written: a drive whose write reaches
// others goes last, the plan's own problems are seen before anything is written.
#include "model/bus/GroupPlan.h"

#include <gtest/gtest.h>

using namespace opentop;

namespace {

BusGroups busWith(std::initializer_list<std::pair<int, std::optional<int>>> drives)
{
    BusGroups groups;
    for (const auto& [slave, group] : drives)
        groups.setGroup(slave, group);
    return groups;
}

} // namespace

TEST(GroupPlan, ADriveWithChildrenIsWrittenAfterTheOthers)
{
    // 2 follows 1; the plan: 1 joins group 5, 2 follows 5 too.
    BusGroups current = busWith({{1, std::nullopt}, {2, 1}, {5, std::nullopt}});
    GroupPlan plan;
    plan.want(1, 5);
    plan.want(2, 5);
    plan.want(5, std::nullopt);
    EXPECT_EQ(plan.differences(current), (QVector<int>{1, 2}));
    // 1 is a parent now: a write to it would reach 2, so 2 goes first.
    EXPECT_EQ(plan.nextWrite(current), 2);
    current.setGroup(2, 5);
    EXPECT_EQ(plan.nextWrite(current), 1);
    current.setGroup(1, 5);
    EXPECT_FALSE(plan.nextWrite(current).has_value());
    EXPECT_TRUE(plan.result(current).problems().isEmpty());
}

TEST(GroupPlan, WhenEveryChangeReachesOthersTheParentGoesFirstAndTheChildIsWrittenAgain)
{
    // 2 follows 1; the plan disables 1's own group but keeps 2 following 1.
    BusGroups current = busWith({{1, 1}, {2, 1}});
    GroupPlan plan;
    plan.want(1, std::nullopt);
    plan.want(2, 1);
    EXPECT_EQ(plan.nextWrite(current), 1);
    // The write to 1 was executed by 2 as well: read back, 2 is disabled too.
    current.setGroup(1, std::nullopt);
    current.setGroup(2, std::nullopt);
    EXPECT_EQ(plan.nextWrite(current), 2);
}

TEST(GroupPlan, AChildIsMovedAfterItsNewParentIsSettledSoNoWriteReachesAnother)
{
    // 2 and 150 follow 1; the plan: 150 leaves the group, 2 follows 150.
    const BusGroups current = busWith({{1, std::nullopt}, {2, 1}, {150, 1}});
    GroupPlan plan;
    plan.want(1, std::nullopt);
    plan.want(2, 150);
    plan.want(150, std::nullopt);
    const QVector<GroupPlan::Step> steps = plan.steps(current);
    ASSERT_EQ(steps.size(), 2);
    EXPECT_EQ(steps[0].slave, 150);
    EXPECT_EQ(steps[1].slave, 2);
    EXPECT_TRUE(steps[0].reaches.isEmpty());
    EXPECT_TRUE(steps[1].reaches.isEmpty());
}

TEST(GroupPlan, StepsSayWhatAWriteToAParentReaches)
{
    const BusGroups current = busWith({{1, 1}, {2, 1}});
    GroupPlan plan;
    plan.want(1, std::nullopt);
    plan.want(2, 1);
    const QVector<GroupPlan::Step> steps = plan.steps(current);
    ASSERT_EQ(steps.size(), 2);
    EXPECT_EQ(steps[0].slave, 1);
    EXPECT_EQ(steps[0].reaches, QVector<int>{2});
    EXPECT_EQ(steps[1].slave, 2);
    EXPECT_EQ(steps[1].group, 1);
}

TEST(GroupPlan, APlansProblemsAreKnownBeforeWriting)
{
    const BusGroups current = busWith({{1, std::nullopt}, {2, std::nullopt}, {3, std::nullopt}});
    GroupPlan plan;
    plan.want(2, 1);
    plan.want(3, 2);  // 2 would be child and parent
    plan.want(1, 99); // no drive 99
    const QVector<BusGroups::Problem> problems = plan.result(current).problems();
    ASSERT_EQ(problems.size(), 2);
    EXPECT_EQ(problems[0].slave, 1);
    EXPECT_EQ(problems[0].kind, BusGroups::ProblemKind::MissingParent);
    EXPECT_EQ(problems[1].slave, 2);
    EXPECT_EQ(problems[1].kind, BusGroups::ProblemKind::Chain);
}

TEST(BusGroups, AlsoReachesTextNamesTheChildren)
{
    BusGroups g;
    g.setGroup(1, std::nullopt);
    g.setGroup(2, 1);
    g.setGroup(150, 1);
    g.setGroup(7, std::nullopt);
    EXPECT_EQ(g.alsoReachesText(1),
              QStringLiteral("This also reaches machine numbers 2 and 150 (the children of "
                             "communication group 1; they execute it without replying)."));
    EXPECT_TRUE(g.alsoReachesText(2).isEmpty());
    g.setGroup(7, 1);
    EXPECT_TRUE(g.alsoReachesText(1).contains(QStringLiteral("2, 7 and 150")));
    g.setGroup(7, 2);
    EXPECT_TRUE(g.alsoReachesText(2).contains(QStringLiteral("machine number 7 (the child")));
    g.removeDrive(7);
    EXPECT_TRUE(g.alsoReachesText(2).isEmpty());
}
