// DBU alarms and warnings: stacks of 15 records (newest first), reset rules, erase commands,
// parameter initialisation and power cycling (manual 7, 12-6 .. 12-9, 13).
#include "tests/sim/SimTestSupport.h"

using namespace opentop;
using namespace opentop::test;

namespace {

class DbuAlarm : public ::testing::Test
{
protected:
    bool console(const char* cmd, const char* value) const
    {
        return sim.bus->control(1, {QString::fromLatin1(cmd), QString::fromLatin1(value)}).ok;
    }
    QVector<quint16> records(quint16 first) const
    {
        QVector<quint16> all;
        for (int i = 0; i < 15; ++i)
            all << sim.read(1, 4, quint16(first + 2 * i)).values.value(0);
        return all;
    }
    void startSpno2()
    {
        ASSERT_TRUE(sim.write(1, "core.control_priority", 2).ok());
        ASSERT_TRUE(sim.write(1, "run.select", 1).ok());
        ASSERT_TRUE(sim.write(1, "run.start", 1).ok());
        sim.advance(1000);
    }
    quint32 status() const { return quint32(sim.raw(1, "status.driver")); }

    SimFixture sim{"dbu200@1"};
};

} // namespace

TEST_F(DbuAlarm, AlarmStopsTheMotorAndIsRecorded)
{
    startSpno2();
    ASSERT_EQ(sim.raw(1, "status.current_speed"), 1000);
    ASSERT_TRUE(console("alarm", "7"));
    sim.advance(10);
    EXPECT_EQ(sim.raw(1, "status.current_speed"), 0);
    EXPECT_TRUE(status() & (1u << 11));
    EXPECT_EQ(sim.readOne(1, "alarm.record1"), 7);
    EXPECT_EQ(sim.readOne(1, "status.outputs") & 2, 2); // Y1 is Alarm-Out by default
    EXPECT_EQ(sim.write(1, "run.start", 1).exception, 0x04);
    EXPECT_EQ(sim.readOne(1, "status.comm_error"), 0xE2);
}

TEST_F(DbuAlarm, StackKeepsFifteenNewestFirst)
{
    const int codes[] = {0x03, 0x05, 0x07, 0x0D, 0x0F, 0x19, 0x21};
    QVector<quint16> pushed;
    for (int i = 0; i < 17; ++i) {
        const int code = codes[i % 7];
        ASSERT_TRUE(console("alarm", QByteArray::number(code).constData()));
        pushed.prepend(quint16(code));
        ASSERT_TRUE(sim.write(1, "cmd.alarm_reset", 0).ok()) << i;
    }
    EXPECT_EQ(records(0x1C01), pushed.mid(0, 15));
    ASSERT_TRUE(sim.write(1, "cmd.erase_alarms", 1).ok());
    EXPECT_EQ(records(0x1C01), QVector<quint16>(15, 0));
}

TEST_F(DbuAlarm, ResetNeedsAlarmResetCodeAndSetting)
{
    ASSERT_TRUE(console("alarm", "0x0B")); // Hall signal error: power cycle only
    EXPECT_EQ(sim.write(1, "cmd.alarm_reset", 0).exception, 0x04);
    EXPECT_EQ(sim.readOne(1, "status.comm_error"), 0xE2);
    EXPECT_TRUE(status() & (1u << 11));
    sim.device(1)->powerCycle(sim.clock->nowMs());
    EXPECT_FALSE(status() & (1u << 11));
    EXPECT_EQ(sim.readOne(1, "alarm.record1"), 0x0B); // records survive

    ASSERT_TRUE(sim.write(1, "core.alarm_erase", 0).ok()); // erase by power reset only
    ASSERT_TRUE(console("alarm", "3"));
    EXPECT_EQ(sim.write(1, "cmd.alarm_reset", 0).exception, 0x04);
    ASSERT_TRUE(sim.write(1, "core.alarm_erase", 1).ok());
    EXPECT_TRUE(sim.write(1, "cmd.alarm_reset", 0).ok());
    EXPECT_FALSE(status() & (1u << 11));
    EXPECT_EQ(sim.write(1, "cmd.alarm_reset", 1).exception, 0x04); // the value must be 0
    EXPECT_EQ(sim.readOne(1, "status.comm_error"), 0xE8);
}

TEST_F(DbuAlarm, UnknownAlarmCodeIsRefusedByTheConsole)
{
    const SimControlResult r = sim.bus->control(1, {QStringLiteral("alarm"), QStringLiteral("2")});
    EXPECT_FALSE(r.ok);
    EXPECT_TRUE(r.text.contains(QStringLiteral("0x0b"))) << r.text.toStdString();
}

TEST_F(DbuAlarm, OverloadWarnsAtOnceAndAlarmsAfterTheOverloadTime)
{
    ASSERT_TRUE(sim.write(1, "alarm.overload_time", 10).ok()); // 1.0 s
    startSpno2();
    ASSERT_TRUE(console("load", "110")); // 20 % + 110 % = 130 %
    sim.advance(100);
    EXPECT_EQ(sim.readOne(1, "warning.record1"), 7);
    EXPECT_FALSE(status() & (1u << 11));
    sim.advance(800);
    EXPECT_FALSE(status() & (1u << 11));
    sim.advance(200);
    EXPECT_TRUE(status() & (1u << 11));
    EXPECT_EQ(sim.readOne(1, "alarm.record1"), 7);
    EXPECT_EQ(sim.readOne(1, "warning.record2"), 0); // the warning was recorded once
}

TEST_F(DbuAlarm, OverSpeedWarnsAbove3500AndAlarmsAbove3800)
{
    ASSERT_TRUE(sim.write(1, "core.upper_limit", 4000).ok());
    ASSERT_TRUE(sim.write(1, "core.control_priority", 2).ok());
    ASSERT_TRUE(sim.write(1, "run.select", 0).ok());
    ASSERT_TRUE(console("vr", "3600"));
    ASSERT_TRUE(sim.write(1, "run.start", 1).ok());
    sim.advance(1500);
    EXPECT_EQ(sim.raw(1, "status.current_speed"), 3600);
    EXPECT_EQ(sim.readOne(1, "warning.record1"), 5);
    EXPECT_FALSE(status() & (1u << 11));
    ASSERT_TRUE(console("vr", "3900"));
    sim.advance(500);
    EXPECT_TRUE(status() & (1u << 11));
    EXPECT_EQ(sim.readOne(1, "alarm.record1"), 5);
}

TEST_F(DbuAlarm, ConsoleWarningsAndErase)
{
    ASSERT_TRUE(console("warning", "0x17"));
    ASSERT_TRUE(console("warning", "0x19"));
    EXPECT_EQ(records(0x1701).mid(0, 3), (QVector<quint16>{0x19, 0x17, 0}));
    ASSERT_TRUE(sim.write(1, "io.y0", 5).ok()); // Warning-Out
    EXPECT_EQ(sim.readOne(1, "status.outputs") & 1, 1);
    ASSERT_TRUE(console("warning", "0"));
    EXPECT_EQ(sim.readOne(1, "status.outputs") & 1, 0);
    ASSERT_TRUE(sim.write(1, "cmd.erase_warnings", 1).ok());
    EXPECT_EQ(records(0x1701), QVector<quint16>(15, 0));
}

TEST_F(DbuAlarm, ExternalErrorInputRaisesAlarm0F)
{
    ASSERT_TRUE(sim.write(1, "io.x3", 0x18).ok()); // Ext-Error: alarm while the input is off
    sim.advance(20);
    EXPECT_TRUE(status() & (1u << 11));
    EXPECT_EQ(sim.readOne(1, "alarm.record1"), 0x0F);
}

TEST_F(DbuAlarm, ParameterInitRestoresEverySetting)
{
    ASSERT_TRUE(sim.write(1, "spno2.speed", 2000).ok());
    ASSERT_TRUE(sim.write(1, "comm.group", 5).ok());
    ASSERT_TRUE(sim.write(1, "core.control_mode", 0).ok());
    ASSERT_TRUE(console("alarm", "3"));
    ASSERT_TRUE(sim.write(1, "cmd.param_init", 1).ok());
    EXPECT_EQ(sim.readOne(1, "spno2.speed"), 1000);
    EXPECT_EQ(sim.readOne(1, "comm.group"), 0xFFFF);
    EXPECT_EQ(sim.readOne(1, "core.control_mode"), 1);
    EXPECT_EQ(sim.readOne(1, "io.x0"), 0x11);
    EXPECT_EQ(sim.readOne(1, "alarm.record1"), 3); // records are not parameters
}

TEST_F(DbuAlarm, SpnoInitResetsOnlyThatSpno)
{
    ASSERT_TRUE(sim.write(1, "spno3.speed", 2000).ok());
    ASSERT_TRUE(sim.write(1, "spno3.accel", 100).ok());
    ASSERT_TRUE(sim.write(1, "spno4.speed", 2000).ok());
    ASSERT_TRUE(sim.write(1, "spno3.init", 1).ok());
    EXPECT_EQ(sim.readOne(1, "spno3.speed"), 1350);
    EXPECT_EQ(sim.readOne(1, "spno3.accel"), 5);
    EXPECT_EQ(sim.readOne(1, "spno4.speed"), 2000);
}

TEST_F(DbuAlarm, PowerCycleKeepsSettingsAndClearsState)
{
    ASSERT_TRUE(sim.write(1, "spno2.speed", 1500).ok());
    ASSERT_TRUE(sim.write(1, "comm.rate", 4).ok()); // 38400, at the next power-on
    EXPECT_EQ(sim.device(1)->lineBaud(), 19200);
    startSpno2();
    ASSERT_TRUE(sim.write(1, "cmd.offline", 1).ok());
    sim.device(1)->powerCycle(sim.clock->nowMs());
    EXPECT_EQ(sim.readOne(1, "spno2.speed"), 1500);
    EXPECT_EQ(sim.readOne(1, "run.select"), 0);
    EXPECT_EQ(sim.raw(1, "status.current_speed"), 0);
    EXPECT_EQ(sim.device(1)->lineBaud(), 38400);
    EXPECT_TRUE(sim.write(1, "run.start", 1).ok()); // online again after power-on
    sim.advance(1000);
    EXPECT_GT(sim.raw(1, "status.current_speed"), 0);
}
