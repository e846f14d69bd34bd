// DBU motion: communication control, speed ramps, SPno selection, direction, limits, I/O
// control, status bits and outputs (manual chapters 7, 9, 12).
#include "tests/sim/SimTestSupport.h"

#include <cmath>

using namespace opentop;
using namespace opentop::test;

namespace {

class DbuMotion : public ::testing::Test
{
protected:
    void SetUp() override
    {
        ASSERT_TRUE(sim.write(1, "core.control_priority", 2).ok());
        ASSERT_TRUE(sim.write(1, "spno2.accel", 50).ok()); // 5.0 s for 0 -> 3000 r/min
        ASSERT_TRUE(sim.write(1, "spno2.decel", 20).ok()); // 2.0 s for 3000 -> 0 r/min
        ASSERT_TRUE(sim.write(1, "run.select", 1).ok());   // SPno2, 1000 r/min
    }

    double speed() const { return sim.raw(1, "status.current_speed"); }
    quint32 status() const { return quint32(sim.raw(1, "status.driver")); }
    bool control(const QString& cmd, const QString& value) const
    {
        return sim.bus->control(1, {cmd, value}).ok;
    }

    SimFixture sim{"dbu200@1"};
};

} // namespace

TEST_F(DbuMotion, RampReachesTargetInTheConfiguredTime)
{
    ASSERT_TRUE(sim.write(1, "run.start", 1).ok());
    // 1000 r/min at 3000 r/min per 5 s: 1.667 s.
    sim.advance(1000);
    EXPECT_NEAR(speed(), 600, 7);
    EXPECT_EQ(sim.raw(1, "status.target_speed"), 1000);
    sim.advance(600);
    EXPECT_LT(speed(), 1000);
    sim.advance(100);
    EXPECT_EQ(speed(), 1000);
    // Over the input registers, as a client sees it.
    EXPECT_EQ(sim.readOne(1, "status.current_speed"), 1000);
    ASSERT_TRUE(sim.write(1, "run.start", 0).ok());
    sim.advance(600); // 1000 -> 0 at 1500 r/min/s: 0.667 s
    EXPECT_NEAR(speed(), 100, 7);
    sim.advance(100);
    EXPECT_EQ(speed(), 0);
    EXPECT_EQ(status() & 0x2, 0u);
}

TEST_F(DbuMotion, StatusBitsShowRunningDirectionSpnoAndMode)
{
    EXPECT_EQ(status(), (1u << 12) | (1u << 8) | (1u << 4)); // Mode2, SPno2, holding
    ASSERT_TRUE(sim.write(1, "run.hold", 1).ok());           // no holding force
    EXPECT_EQ(status(), (1u << 12) | (1u << 8));
    ASSERT_TRUE(sim.write(1, "spno2.direction", 1).ok());
    ASSERT_TRUE(sim.write(1, "run.start", 1).ok());
    sim.advance(200);
    const quint32 s = status();
    EXPECT_TRUE(s & (1u << 1));   // running
    EXPECT_TRUE(s & (1u << 2));   // CCW from the SPno's direction register
    EXPECT_FALSE(s & (1u << 4));  // no hold while running
    EXPECT_FALSE(s & (1u << 11)); // no alarm
    // 32-bit, high word first.
    const Answer a = sim.read(1, 4, 0x0065, 2);
    EXPECT_EQ(a.values, (QVector<quint16>{0, quint16(s)}));
}

TEST_F(DbuMotion, RunDirectionOverridesUntilTheSpnoChanges)
{
    ASSERT_TRUE(sim.write(1, "run.direction", 1).ok());
    ASSERT_TRUE(sim.write(1, "run.start", 1).ok());
    sim.advance(2000);
    EXPECT_TRUE(status() & (1u << 2));
    ASSERT_TRUE(sim.write(1, "run.select", 2).ok()); // SPno3: its own direction, CW
    sim.advance(5000);
    EXPECT_FALSE(status() & (1u << 2));
    EXPECT_EQ(speed(), 1350);
}

TEST_F(DbuMotion, ReversingDeceleratesThroughZero)
{
    ASSERT_TRUE(sim.write(1, "run.start", 1).ok());
    sim.advance(2000);
    ASSERT_EQ(speed(), 1000);
    ASSERT_TRUE(sim.write(1, "run.direction", 1).ok());
    sim.advance(300); // decelerating at 1500 r/min/s
    EXPECT_NEAR(speed(), 550, 7);
    EXPECT_FALSE(status() & (1u << 2));
    sim.advance(2500); // 0.37 s more to 0, then 1.67 s to 1000 CCW
    EXPECT_EQ(speed(), 1000);
    EXPECT_TRUE(status() & (1u << 2));
}

TEST_F(DbuMotion, Spno1RunsAtTheExtVrSpeed)
{
    ASSERT_TRUE(control(QStringLiteral("vr"), QStringLiteral("800")));
    EXPECT_EQ(sim.readOne(1, "spno1.speed"), 800);
    ASSERT_TRUE(sim.write(1, "run.select", 0).ok());
    ASSERT_TRUE(sim.write(1, "run.start", 1).ok());
    sim.advance(100); // SS VR: 1 s for 3000 r/min
    EXPECT_NEAR(speed(), 300, 7);
    sim.advance(200);
    EXPECT_EQ(speed(), 800);
}

TEST_F(DbuMotion, SpeedLimitsClampTheTarget)
{
    ASSERT_TRUE(sim.write(1, "core.upper_limit", 1200).ok());
    ASSERT_TRUE(sim.write(1, "run.select", 7).ok()); // SPno8, 3000 r/min
    ASSERT_TRUE(sim.write(1, "run.start", 1).ok());
    sim.advance(100);
    EXPECT_EQ(sim.raw(1, "status.target_speed"), 1200);
    ASSERT_TRUE(sim.write(1, "core.lower_limit", 1500).ok());
    ASSERT_TRUE(sim.write(1, "core.upper_limit", 3000).ok());
    ASSERT_TRUE(sim.write(1, "run.select", 1).ok()); // SPno2, 1000 r/min
    sim.advance(100);
    EXPECT_EQ(sim.raw(1, "status.target_speed"), 1500);
}

TEST_F(DbuMotion, OfflineForcesIoBehaviourAndStops)
{
    ASSERT_TRUE(sim.write(1, "run.start", 1).ok());
    sim.advance(2000);
    ASSERT_TRUE(sim.write(1, "cmd.offline", 1).ok());
    sim.advance(1000);
    EXPECT_EQ(speed(), 0);
    ASSERT_TRUE(sim.write(1, "cmd.connect", 1).ok());
    sim.advance(1000);
    EXPECT_EQ(speed(), 0); // a new START is needed after reconnecting
}

TEST_F(DbuMotion, IgnoreStopAcknowledgesButKeepsRunning)
{
    ASSERT_TRUE(control(QStringLiteral("ignore-stop"), QStringLiteral("on")));
    ASSERT_TRUE(sim.write(1, "run.start", 1).ok());
    sim.advance(2000);
    const Answer stop = sim.write(1, "run.start", 0);
    EXPECT_TRUE(stop.ok());
    sim.advance(2000);
    EXPECT_EQ(speed(), 1000);
    ASSERT_TRUE(control(QStringLiteral("ignore-stop"), QStringLiteral("off")));
    ASSERT_TRUE(sim.write(1, "run.start", 0).ok());
    sim.advance(2000);
    EXPECT_EQ(speed(), 0);
}

TEST_F(DbuMotion, IoPriorityFollowsTheInputs)
{
    ASSERT_TRUE(sim.write(1, "core.control_priority", 1).ok());
    // Mode2 defaults: X0 CW/STOP, X1 CCW/STOP, X2 M0, X3 M1.
    ASSERT_TRUE(control(QStringLiteral("input"), QStringLiteral("0x5"))); // CW, M0: SPno2
    sim.advance(3000);
    EXPECT_EQ(speed(), 1000);
    EXPECT_EQ(sim.readOne(1, "status.inputs"), 5);
    ASSERT_TRUE(control(QStringLiteral("input"), QStringLiteral("0x3"))); // CW and CCW: stop
    sim.advance(3000);
    EXPECT_EQ(speed(), 0);
    ASSERT_TRUE(control(QStringLiteral("input"), QStringLiteral("0xE"))); // CCW, M0, M1: SPno4
    sim.advance(5000);
    EXPECT_EQ(speed(), 1700);
    EXPECT_TRUE(status() & (1u << 2));
    EXPECT_EQ((status() >> 8) & 7, 3u);
}

TEST_F(DbuMotion, OutputsFollowTheirFunctions)
{
    ASSERT_TRUE(sim.write(1, "io.y0", 2).ok()); // Reach Speed-Out
    ASSERT_TRUE(sim.write(1, "io.y1", 6).ok()); // Move-Out
    EXPECT_EQ(sim.readOne(1, "status.outputs"), 0);
    ASSERT_TRUE(sim.write(1, "run.start", 1).ok());
    sim.advance(500);
    EXPECT_EQ(sim.readOne(1, "status.outputs"), 2); // moving, not there yet
    sim.advance(2000);
    EXPECT_EQ(sim.readOne(1, "status.outputs"), 3);
    ASSERT_TRUE(sim.write(1, "io.y0", 3).ok()); // VA-Out: within va.speed (200) of the target
    ASSERT_TRUE(sim.write(1, "spno3.accel", 50).ok());
    ASSERT_TRUE(sim.write(1, "run.select", 2).ok()); // to 1350 r/min
    sim.advance(100);
    EXPECT_EQ(sim.readOne(1, "status.outputs"), 2);
    sim.advance(1000);
    EXPECT_EQ(sim.readOne(1, "status.outputs"), 3);
}

TEST_F(DbuMotion, LoadRisesWithSpeedAndAcceleration)
{
    EXPECT_EQ(sim.readOne(1, "status.load"), 0);
    ASSERT_TRUE(sim.write(1, "run.start", 1).ok());
    sim.advance(500);
    const double accelerating = sim.readOne(1, "status.load");
    sim.advance(2000);
    const double steady = sim.readOne(1, "status.load");
    EXPECT_EQ(steady, 20); // 10 % + 30 % x 1000/3000
    EXPECT_GT(accelerating, 15);
    ASSERT_TRUE(control(QStringLiteral("load"), QStringLiteral("50")));
    sim.advance(10);
    EXPECT_EQ(sim.readOne(1, "status.load"), 70);
}

TEST_F(DbuMotion, ParameterInitRefusedWhileRunning)
{
    ASSERT_TRUE(sim.write(1, "run.start", 1).ok());
    EXPECT_EQ(sim.write(1, "cmd.param_init", 1).exception, 0x04);
    EXPECT_EQ(sim.readOne(1, "status.comm_error"), 0xE2);
}
