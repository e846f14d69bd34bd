// Defects of a simulated DC PID controller as a master sees them over Modbus: another firmware
// (version register and 2B/0E revision), a motor that saturates below its speed or stalls, a
// current too high, the stall stop while running, a setting that does not stick or is not
// stored. Controller 7 is good, controller 8 has defects: both get the same frames.
#include "tests/sim/SimTestSupport.h"

#include "transport/DeviceIdentification.h"

using namespace opentop;
using namespace opentop::test;

namespace {

class DcPidDefect : public ::testing::Test
{
protected:
    void defect(const char* spec)
    {
        const SimControlResult r =
            sim.bus->control(8, {QStringLiteral("defect"), QString::fromLatin1(spec)});
        ASSERT_TRUE(r.ok) << r.text.toStdString();
    }
    // 80 % PWM on both (speed mode 0, the default).
    void runBoth(quint16 command = 800)
    {
        for (int id : {7, 8})
            ASSERT_TRUE(sim.write(id, "speed.command", command).ok());
    }
    quint16 turning(int id) const { return sim.readOne(id, "status.commutation"); }
    quint16 current(int id) const { return sim.readOne(id, "status.current"); }
    quint16 pwm(int id) const { return sim.readOne(id, "status.pwm"); }

    SimFixture sim{"dcpid@7,dcpid@8"};
};

} // namespace

TEST_F(DcPidDefect, FirmwareIsInTheVersionRegisterAndTheIdentification)
{
    defect("firmware=2.1");
    EXPECT_EQ(sim.readOne(8, "info.version"), 0x0201);
    EXPECT_EQ(sim.readOne(7, "info.version"), 0x0100);
    const Answer a = sim.send(withCrc(hexBytes("08 2B 0E 04 02")));
    ASSERT_TRUE(a.ok());
    DeviceIdentification id;
    ASSERT_TRUE(DeviceIdentification::parse(a.adu.mid(2, a.adu.size() - 4), &id));
    EXPECT_EQ(id.objects.value(2), QByteArray("V2.1"));
    defect("clear");
    EXPECT_EQ(sim.readOne(8, "info.version"), 0x0100);
}

TEST_F(DcPidDefect, MaxSpeedSaturatesWithMoreCurrent)
{
    defect("max_speed=500");
    runBoth();
    sim.advance(1000);
    EXPECT_NEAR(turning(7), 790, 10);
    EXPECT_EQ(turning(8), 500); // commutations per second held below the output's
    EXPECT_EQ(pwm(7), 800);
    EXPECT_LT(pwm(8), 800); // the current limit takes the output back
    EXPECT_EQ(current(8), sim.readOne(8, "config.max_current"));
    EXPECT_GT(current(8), current(7) * 1.4);
}

TEST_F(DcPidDefect, StalledMotorDrawsMaximumCurrentUntilTheStallStop)
{
    defect("stall");
    runBoth();
    sim.advance(2000);
    EXPECT_EQ(turning(8), 0);
    EXPECT_EQ(current(8), sim.readOne(8, "config.max_current"));
    EXPECT_GT(pwm(8), 100); // no stall stop configured: it keeps pushing, current-limited
    // With a stall stop time the controller brakes by itself (1.0 s).
    runBoth(0);
    sim.advance(500);
    ASSERT_TRUE(sim.write(8, "config.stall_time", 10).ok());
    runBoth();
    sim.advance(900);
    EXPECT_GT(pwm(8), 100);
    sim.advance(500); // 1.0 s stalled, then braking
    EXPECT_EQ(pwm(8), 0);
    EXPECT_EQ(current(8), 0);
    EXPECT_EQ(pwm(7), 800);
    EXPECT_TRUE(sim.device(8)->stateText().contains(QStringLiteral("stall stop")));
}

TEST_F(DcPidDefect, LoadRaisesTheCurrent)
{
    defect("load=+40");
    runBoth();
    sim.advance(1000);
    EXPECT_EQ(turning(8), turning(7));
    EXPECT_NEAR(current(8), current(7) * 1.4, 1);
    defect("load=+0,load=x1.5");
    sim.advance(100);
    EXPECT_NEAR(current(8), current(7) * 1.5, 1);
}

TEST_F(DcPidDefect, AlarmWhileRunningIsTheStallStop)
{
    defect("alarm=stall@1500ms");
    runBoth();
    sim.advance(1400);
    EXPECT_EQ(pwm(8), 800);
    sim.advance(600); // stopped at 1.5 s, braked to 0 within 0.5 s
    EXPECT_EQ(pwm(8), 0);
    EXPECT_EQ(turning(8), 0);
    EXPECT_EQ(pwm(7), 800);
    EXPECT_TRUE(sim.device(8)->stateText().contains(QStringLiteral("stall stop")));
    runBoth(); // a new command runs it again, until the defect strikes again
    sim.advance(1000);
    EXPECT_EQ(pwm(8), 800);
    EXPECT_FALSE(sim.device(8)->stateText().contains(QStringLiteral("stall stop")));
}

TEST_F(DcPidDefect, SettingThatDoesNotStickIsAcknowledgedButKeepsItsOldValue)
{
    defect("nostick=config.rated_current");
    const Answer a = sim.write(8, "config.rated_current", 700);
    ASSERT_TRUE(a.ok());
    EXPECT_EQ(a.adu.mid(1, 5), hexBytes("06 00 86 02 BC"));
    EXPECT_EQ(sim.readOne(8, "config.rated_current"), 500);
    ASSERT_TRUE(sim.write(8, "config.brake_current", 300).ok()); // other settings stick
    EXPECT_EQ(sim.readOne(8, "config.brake_current"), 300);
}

TEST_F(DcPidDefect, SettingNotStoredIsLostAtPowerCycle)
{
    defect("nostore=0x0086"); // config.rated_current by its address
    for (int id : {7, 8}) {
        ASSERT_TRUE(sim.write(id, "config.rated_current", 700).ok());
        ASSERT_TRUE(sim.write(id, "config.brake_current", 300).ok());
        ASSERT_TRUE(sim.write(id, "store.config", 1).ok());
        EXPECT_EQ(sim.readOne(id, "config.rated_current"), 700);
        sim.device(id)->powerCycle(sim.clock->nowMs());
    }
    EXPECT_EQ(sim.readOne(7, "config.rated_current"), 700);
    EXPECT_EQ(sim.readOne(8, "config.rated_current"), 500); // the store did not keep it
    EXPECT_EQ(sim.readOne(8, "config.brake_current"), 300);
}
