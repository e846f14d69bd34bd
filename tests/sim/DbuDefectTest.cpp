// Defects of a simulated DBU drive as a master sees them over Modbus: another firmware, a motor
// that saturates below its target or stalls, a load too high, an alarm while running, a setting
// that does not stick or is not kept over a power cycle. Drive 1 is good, drive 2 has defects:
// both get the same frames.
#include "tests/sim/SimTestSupport.h"

using namespace opentop;
using namespace opentop::test;

namespace {

constexpr quint32 kRunning = 1u << 1;
constexpr quint32 kAlarm = 1u << 11;

class DbuDefect : public ::testing::Test
{
protected:
    void defect(const char* spec)
    {
        const SimControlResult r =
            sim.bus->control(2, {QStringLiteral("defect"), QString::fromLatin1(spec)});
        ASSERT_TRUE(r.ok) << r.text.toStdString();
    }
    // Communication priority, SPno2 (1000 r/min) with a 0.5 s ramp, started on both drives.
    void startBoth()
    {
        for (int id : {1, 2}) {
            ASSERT_TRUE(sim.write(id, "core.control_priority", 2).ok());
            ASSERT_TRUE(sim.write(id, "run.select", 1).ok());
            ASSERT_TRUE(sim.write(id, "run.start", 1).ok());
        }
    }
    quint16 speed(int id) const { return sim.readOne(id, "status.current_speed"); }
    quint16 load(int id) const { return sim.readOne(id, "status.load"); }
    quint32 driver(int id) const
    {
        const Answer a = sim.read(id, 4, sim.address(id, "status.driver"), 2);
        EXPECT_TRUE(a.ok());
        return a.values.size() == 2 ? (quint32(a.values.at(0)) << 16) | a.values.at(1) : 0;
    }

    SimFixture sim{"dbu200@1,dbu200@2"};
};

} // namespace

TEST_F(DbuDefect, FirmwareIsWhatIdentificationReads)
{
    const quint16 version = sim.address(2, "info.version");
    EXPECT_EQ(sim.read(2, 4, version).values.value(0), 0x0105);
    defect("firmware=1.4");
    EXPECT_EQ(sim.read(2, 4, version).values.value(0), 0x0104);
    EXPECT_EQ(sim.read(1, 4, version).values.value(0), 0x0105); // the good drive
    sim.device(2)->powerCycle(sim.clock->nowMs());
    EXPECT_EQ(sim.read(2, 4, version).values.value(0), 0x0104); // it is the firmware
    defect("firmware=2.15");
    EXPECT_EQ(sim.read(2, 4, version).values.value(0), 0x020F);
    defect("clear");
    EXPECT_EQ(sim.read(2, 4, version).values.value(0), 0x0105);
}

TEST_F(DbuDefect, MaxSpeedSaturatesBelowTheTargetAtTheTorqueLimit)
{
    defect("max_speed=800");
    startBoth();
    sim.advance(3000);
    EXPECT_EQ(speed(1), 1000);
    EXPECT_EQ(speed(2), 800);
    EXPECT_EQ(sim.readOne(2, "status.target_speed"), 1000); // the target is unchanged
    EXPECT_GE(load(2), 110);
    EXPECT_LT(load(2), 120); // below the overload threshold: no alarm however long it runs
    sim.advance(10000);
    EXPECT_EQ(speed(2), 800);
    EXPECT_TRUE(driver(2) & kRunning);
    EXPECT_FALSE(driver(2) & kAlarm);
    EXPECT_EQ(sim.readOne(2, "alarm.record1"), 0);
}

TEST_F(DbuDefect, StalledMotorStaysAtZeroAndTripsOverload)
{
    defect("stall");
    startBoth();
    sim.advance(1000);
    EXPECT_EQ(speed(1), 1000);
    EXPECT_EQ(speed(2), 0);
    EXPECT_GE(load(2), 120); // above the overload threshold
    EXPECT_TRUE(driver(2) & kRunning);
    sim.advance(2500); // alarm.overload_time 3.0 s
    EXPECT_TRUE(driver(2) & kAlarm);
    EXPECT_FALSE(driver(2) & kRunning);
    EXPECT_EQ(sim.readOne(2, "alarm.record1"), 0x07); // overload
    EXPECT_FALSE(driver(1) & kAlarm);
}

TEST_F(DbuDefect, LoadOffsetAndFactor)
{
    defect("load=+40");
    startBoth();
    sim.advance(2000);
    EXPECT_EQ(speed(2), 1000); // reaches its speed, only the load is high
    EXPECT_EQ(load(2), load(1) + 40);
    defect("load=+0,load=x2");
    sim.advance(100);
    EXPECT_EQ(load(2), 2 * load(1));
    // Not running: no load, whatever the defect.
    for (int id : {1, 2})
        ASSERT_TRUE(sim.write(id, "run.start", 0).ok());
    sim.advance(2000);
    EXPECT_EQ(load(2), 0);
}

TEST_F(DbuDefect, AlarmWhileRunningStopsTheDriveAndIsRecorded)
{
    defect("alarm=overload@1500ms");
    startBoth();
    sim.advance(1400);
    EXPECT_EQ(speed(2), 1000);
    EXPECT_FALSE(driver(2) & kAlarm);
    sim.advance(200);
    EXPECT_TRUE(driver(2) & kAlarm);
    EXPECT_FALSE(driver(2) & kRunning);
    EXPECT_EQ(speed(2), 0); // free-run stop at once, as on any alarm
    EXPECT_EQ(sim.readOne(2, "alarm.record1"), 0x07);
    EXPECT_EQ(speed(1), 1000);
    // A start is refused while the alarm is active (exception 04), and works after a reset.
    EXPECT_EQ(sim.write(2, "run.start", 1).exception, 0x04);
    ASSERT_TRUE(sim.write(2, "cmd.alarm_reset", 0).ok());
    ASSERT_TRUE(sim.write(2, "run.start", 1).ok());
    sim.advance(1000);
    EXPECT_EQ(speed(2), 1000);
    sim.advance(600); // the defect comes back on every run
    EXPECT_TRUE(driver(2) & kAlarm);
    EXPECT_EQ(sim.readOne(2, "alarm.record2"), 0x07);
}

TEST_F(DbuDefect, SettingThatDoesNotStickIsAcknowledgedButKeepsItsOldValue)
{
    defect("nostick=spno2.speed");
    const Answer a = sim.write(2, "spno2.speed", 1500);
    ASSERT_TRUE(a.ok());
    EXPECT_EQ(a.adu.mid(1, 5), hexBytes("06 CA 03 05 DC")); // echoed like any accepted write
    ASSERT_TRUE(sim.write(1, "spno2.speed", 1500).ok());
    EXPECT_EQ(sim.readOne(1, "spno2.speed"), 1500);
    EXPECT_EQ(sim.readOne(2, "spno2.speed"), 1000);
    ASSERT_TRUE(sim.write(2, "spno3.speed", 2000).ok()); // other settings stick
    EXPECT_EQ(sim.readOne(2, "spno3.speed"), 2000);
    // By address, from the console.
    defect("nostick=0xCA05");
    ASSERT_TRUE(sim.write(2, "spno3.speed", 900).ok());
    EXPECT_EQ(sim.readOne(2, "spno3.speed"), 2000);
}

TEST_F(DbuDefect, SettingNotSavedIsLostAtPowerCycle)
{
    defect("nostore=spno2.speed");
    ASSERT_TRUE(sim.write(2, "spno2.speed", 1500).ok());
    ASSERT_TRUE(sim.write(2, "spno3.speed", 2000).ok());
    EXPECT_EQ(sim.readOne(2, "spno2.speed"), 1500); // taken until the power goes
    sim.device(2)->powerCycle(sim.clock->nowMs());
    EXPECT_EQ(sim.readOne(2, "spno2.speed"), 1000);
    EXPECT_EQ(sim.readOne(2, "spno3.speed"), 2000);
}

TEST_F(DbuDefect, ConsoleErrorsChangeNothing)
{
    defect("max_speed=800");
    const SimControlResult r =
        sim.bus->control(2, {QStringLiteral("defect"), QStringLiteral("alarm=0x02@1s")});
    EXPECT_FALSE(r.ok);
    EXPECT_TRUE(r.text.contains(QStringLiteral("0x07 overload"))) << r.text.toStdString();
    EXPECT_EQ(sim.device(2)->defects().spec.toString(), QStringLiteral("max_speed=800"));
    EXPECT_FALSE(sim.bus->control(2, {QStringLiteral("defect")}).ok);
}
