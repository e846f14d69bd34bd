#include "model/session/ReadPlanner.h"
#include "model/profile/ProfileRegistry.h"

#include <gtest/gtest.h>

using namespace opentop;

namespace {

QVector<const ParameterMeta*> all(const Profile& p, bool backupOnly)
{
    QVector<const ParameterMeta*> result;
    for (const ParameterMeta& m : p.parameters) {
        if (m.isReadable() && (!backupOnly || m.backup))
            result << &m;
    }
    return result;
}

} // namespace

TEST(ReadPlanner, BlocksStayInsideReadBlocksAndTheDeviceLimit)
{
    const Profile& dbu = *ProfileRegistry::builtIn().family(QStringLiteral("dbu"));
    const QVector<const ParameterMeta*> params = all(dbu, true);
    const QVector<ReadBlockPlan> plans = ReadPlanner::plan(dbu, params);
    int covered = 0;
    for (const ReadBlockPlan& plan : plans) {
        EXPECT_LE(plan.count, dbu.maxReadRegisters);
        EXPECT_GE(plan.count, 1);
        for (const ParameterMeta* m : plan.parameters) {
            EXPECT_EQ(m->readFunction, plan.function);
            EXPECT_GE(m->address, plan.address);
            EXPECT_LE(m->address + m->registerCount, plan.address + plan.count)
                << qPrintable(m->name);
        }
        if (plan.parameters.size() > 1) {
            const bool inside =
                std::any_of(dbu.readBlocks.begin(), dbu.readBlocks.end(), [&](const ReadBlock& b) {
                    return b.function == plan.function && plan.address >= b.first &&
                           plan.address + plan.count - 1 <= b.last;
                });
            EXPECT_TRUE(inside) << plan.address;
        }
        covered += plan.parameters.size();
    }
    EXPECT_EQ(covered, params.size());
    // Far fewer requests than parameters: that is the point.
    EXPECT_LT(plans.size(), params.size() / 3) << plans.size() << " requests for " << params.size();
}

TEST(ReadPlanner, ParametersOutsideReadBlocksAreReadAlone)
{
    const Profile& dbu = *ProfileRegistry::builtIn().family(QStringLiteral("dbu"));
    Profile bare = dbu;
    bare.readBlocks.clear();
    bare.index();
    const QVector<const ParameterMeta*> params = all(bare, true);
    EXPECT_EQ(ReadPlanner::plan(bare, params).size(), params.size());
    EXPECT_EQ(ReadPlanner::singles(params).size(), params.size());
}
