// Communication groups: who is parent or child, what a write to a machine number also reaches,
// and the two setups that are wrong (a chain, a child of a drive nobody knows).
#include "model/bus/BusGroups.h"
#include "model/profile/ProfileRegistry.h"

#include <gtest/gtest.h>

using namespace opentop;

namespace {

BusGroups busWith(std::initializer_list<std::pair<int, qint64>> drives)
{
    BusGroups groups;
    for (const auto& [slave, raw] : drives)
        groups.setGroupRaw(slave, raw);
    return groups;
}

} // namespace

TEST(BusGroups, ChildrenAndParentsFollowTheGroupNumber)
{
    // 1 disabled, 3 and 5 in group 1, 7 in its own group (a parent without children).
    const BusGroups g = busWith({{1, 0xFFFF}, {3, 1}, {5, 1}, {7, 7}});
    EXPECT_EQ(g.childrenOf(1), (QVector<int>{3, 5}));
    EXPECT_EQ(g.parentOf(3), 1);
    EXPECT_EQ(g.parentOf(5), 1);
    EXPECT_FALSE(g.parentOf(1).has_value());
    EXPECT_FALSE(g.parentOf(7).has_value()); // its own group: no child
    EXPECT_TRUE(g.childrenOf(7).isEmpty());
    EXPECT_TRUE(g.childrenOf(3).isEmpty());
    EXPECT_TRUE(g.isParent(1));
    EXPECT_FALSE(g.isParent(7));
    EXPECT_TRUE(g.isChild(3));
    EXPECT_TRUE(g.problems().isEmpty());
    EXPECT_EQ(g.roleText(1), QStringLiteral("parent of 3, 5"));
    EXPECT_EQ(g.roleText(3), QStringLiteral("child of 1"));
    EXPECT_EQ(g.roleText(7), QStringLiteral("—"));
    EXPECT_TRUE(g.reachText(1).contains(QStringLiteral("also executed by 3, 5")));
    EXPECT_TRUE(g.reachText(3).isEmpty());
}

TEST(BusGroups, RawValuesOutsideOneTo247AreDisabled)
{
    EXPECT_FALSE(BusGroups::groupFromRaw(0xFFFF).has_value());
    EXPECT_FALSE(BusGroups::groupFromRaw(0).has_value());
    EXPECT_FALSE(BusGroups::groupFromRaw(248).has_value());
    EXPECT_EQ(BusGroups::groupFromRaw(1), 1);
    EXPECT_EQ(BusGroups::groupFromRaw(247), 247);
    BusGroups g;
    g.addDrive(4); // known, group unknown or none
    EXPECT_EQ(g.drives(), QVector<int>{4});
    EXPECT_FALSE(g.groupOf(4).has_value());
}

TEST(BusGroups, AChainAndAMissingParentAreProblems)
{
    // 3 is a child of 1 and the parent of 5: a chain. 9 is in group 20, which nobody is.
    const BusGroups g = busWith({{1, 0xFFFF}, {3, 1}, {5, 3}, {9, 20}});
    const QVector<BusGroups::Problem> problems = g.problems();
    ASSERT_EQ(problems.size(), 2);
    EXPECT_EQ(problems[0].kind, BusGroups::ProblemKind::Chain);
    EXPECT_EQ(problems[0].slave, 3);
    EXPECT_EQ(problems[0].group, 1);
    EXPECT_EQ(problems[1].kind, BusGroups::ProblemKind::MissingParent);
    EXPECT_EQ(problems[1].slave, 9);
    EXPECT_EQ(problems[1].group, 20);
    EXPECT_TRUE(BusGroups::describe(problems[1]).contains(QStringLiteral("no drive 20")));
    EXPECT_EQ(g.roleText(3), QStringLiteral("child of 1; parent of 5"));
    // Only direct children: a write to 1 is not passed on by 3 to 5.
    EXPECT_EQ(g.childrenOf(1), QVector<int>{3});
}

TEST(BusGroups, TheGroupParameterComesFromTheProfileRole)
{
    const ProfileRegistry& registry = ProfileRegistry::builtIn();
    ASSERT_NE(registry.family(QStringLiteral("dbu")), nullptr);
    EXPECT_EQ(BusGroups::groupParameter(*registry.family(QStringLiteral("dbu"))),
              QStringLiteral("comm.group"));
    ASSERT_NE(registry.family(QStringLiteral("dcpid")), nullptr);
    EXPECT_TRUE(BusGroups::groupParameter(*registry.family(QStringLiteral("dcpid"))).isEmpty());
}
