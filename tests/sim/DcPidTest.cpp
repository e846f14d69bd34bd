// The DC motor PID controller (its manual, section 1): functions, exceptions, speed modes and
// ramps, temporary versus stored configuration, communication loss braking, identification.
#include "tests/sim/SimTestSupport.h"

#include "sim/DcPidSimDevice.h"
#include "transport/DeviceIdentification.h"

#include <cstring>

using namespace opentop;
using namespace opentop::test;

namespace {

class DcPid : public ::testing::Test
{
protected:
    void powerCycle() { sim.device(7)->powerCycle(sim.clock->nowMs()); }
    double pwm() const { return sim.raw(7, "status.pwm"); }

    SimFixture sim{"dcpid@7"};
};

QVector<quint16> floatRegisters(float value)
{
    quint32 bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    return {quint16(bits >> 16), quint16(bits & 0xFFFF)};
}

} // namespace

TEST_F(DcPid, SupportsOnly03061015And2B)
{
    EXPECT_EQ(sim.read(7, 4, 0x0010).exception, 0x01);
    EXPECT_EQ(sim.send(withCrc(hexBytes("07 01 00 00 00 01"))).exception, 0x01);
    EXPECT_TRUE(sim.read(7, 3, 0x0010).ok());
}

TEST_F(DcPid, DeviceNameIsNulPadded)
{
    const Answer a = sim.read(7, 3, 0x0002, 8);
    ASSERT_TRUE(a.ok());
    QByteArray text;
    for (quint16 v : a.values)
        text.append(char(v >> 8)).append(char(v & 0xFF));
    EXPECT_EQ(text, QByteArray("DCPID-20A\0\0\0\0\0\0\0", 16));
}

TEST_F(DcPid, ReadDeviceIdentification)
{
    const Answer a = sim.send(withCrc(hexBytes("07 2B 0E 01 00")));
    ASSERT_TRUE(a.replied);
    ASSERT_TRUE(ModbusCrc::check(a.adu));
    DeviceIdentification id;
    ASSERT_TRUE(DeviceIdentification::parse(a.adu.mid(2, a.adu.size() - 4), &id));
    EXPECT_EQ(id.objects.value(1), QByteArray("DCPID-20A"));
    EXPECT_EQ(id.objects.value(2), QByteArray("V1.0"));
    EXPECT_EQ(id.objects.size(), 3);
    const Answer one = sim.send(withCrc(hexBytes("07 2B 0E 04 02")));
    ASSERT_TRUE(DeviceIdentification::parse(one.adu.mid(2, one.adu.size() - 4), &id));
    EXPECT_EQ(id.objects.keys(), (QList<quint8>{2}));
    EXPECT_EQ(sim.send(withCrc(hexBytes("07 2B 0E 04 05"))).exception, 0x02);
    EXPECT_EQ(sim.send(withCrc(hexBytes("07 2B 0E 07 00"))).exception, 0x03);
}

TEST_F(DcPid, ExceptionCodes)
{
    EXPECT_EQ(sim.read(7, 3, 0x0020).exception, 0x02);
    EXPECT_EQ(sim.write(7, 0x0010, 5).exception, 0x02);             // read-only status
    EXPECT_EQ(sim.write(7, "speed.command", 1001).exception, 0x03); // PWM mode: -1000..1000
    EXPECT_EQ(sim.write(7, "config.speed_mode", 4).exception, 0x03);
    EXPECT_EQ(sim.read(7, 3, 0x0000, 126).exception, 0x03);
    ASSERT_TRUE(sim.write(7, "config.speed_mode", 1).ok()); // torque: -2000..2000 (0.01 A)
    EXPECT_TRUE(sim.write(7, "speed.command", 2000).ok());
}

TEST_F(DcPid, LockedSerialSettingsAreProhibited)
{
    ASSERT_TRUE(sim.write(7, "config.serial_lock", 1).ok());
    EXPECT_EQ(sim.write(7, "config.parity", 0).exception, 0x40);
    EXPECT_EQ(sim.writeMany(7, 0x008A, {0, 19200}).exception, 0x40);
    EXPECT_TRUE(sim.write(7, "config.parity", quint16(sim.raw(7, "config.parity"))).ok());
    ASSERT_TRUE(sim.write(7, "config.serial_lock", 0).ok());
    EXPECT_TRUE(sim.write(7, "config.parity", 0).ok());
}

TEST_F(DcPid, SingleWritesAreTemporary)
{
    ASSERT_TRUE(sim.write(7, "config.speed_mode", 2).ok());
    EXPECT_EQ(sim.readOne(7, "config.speed_mode"), 2);
    powerCycle();
    EXPECT_EQ(sim.readOne(7, "config.speed_mode"), 0);
}

TEST_F(DcPid, FifteenRegisterWriteStoresTheConfiguration)
{
    Answer block = sim.read(7, 3, 0x0080, 15);
    ASSERT_TRUE(block.ok());
    QVector<quint16> values = block.values;
    values[0] = 2;                                                 // speed mode
    values[0x0E] = 5;                                              // comm loss 0.5 s
    ASSERT_TRUE(sim.writeMany(7, 0x0080, values.mid(0, 14)).ok()); // short: temporary
    powerCycle();
    EXPECT_EQ(sim.readOne(7, "config.speed_mode"), 0);
    ASSERT_TRUE(sim.writeMany(7, 0x0080, values).ok());
    powerCycle();
    EXPECT_EQ(sim.readOne(7, "config.speed_mode"), 2);
    EXPECT_EQ(sim.readOne(7, "config.comm_loss_time"), 5);
}

TEST_F(DcPid, StoreAndReloadCommands)
{
    ASSERT_TRUE(sim.write(7, "config.rated_current", 700).ok());
    ASSERT_TRUE(sim.write(7, "store.config", 1).ok());
    ASSERT_TRUE(sim.write(7, "config.rated_current", 900).ok());
    ASSERT_TRUE(sim.write(7, "store.config", 0).ok()); // reload: back to the stored 7.00 A
    EXPECT_EQ(sim.readOne(7, "config.rated_current"), 700);
    powerCycle();
    EXPECT_EQ(sim.readOne(7, "config.rated_current"), 700);
}

TEST_F(DcPid, PidFloatsStoredBySevenRegistersOrCommand)
{
    const QVector<quint16> p = floatRegisters(0.25f);
    ASSERT_TRUE(sim.write(7, 0x0090, p[0]).ok()); // by halves with 06
    ASSERT_TRUE(sim.write(7, 0x0091, p[1]).ok());
    EXPECT_DOUBLE_EQ(sim.raw(7, "pid.p"), 0.25);
    powerCycle();
    EXPECT_DOUBLE_EQ(sim.raw(7, "pid.p"), 0.1f);
    QVector<quint16> seven = floatRegisters(0.5f) + floatRegisters(0.05f) + floatRegisters(0.0f);
    seven << 0;
    ASSERT_TRUE(sim.writeMany(7, 0x0090, seven).ok());
    powerCycle();
    EXPECT_DOUBLE_EQ(sim.raw(7, "pid.p"), 0.5);
    EXPECT_DOUBLE_EQ(sim.raw(7, "pid.i"), 0.05f);
    ASSERT_TRUE(sim.writeMany(7, 0x0092, floatRegisters(0.2f)).ok());
    ASSERT_TRUE(sim.write(7, "store.pid", 1).ok());
    powerCycle();
    EXPECT_DOUBLE_EQ(sim.raw(7, "pid.i"), 0.2f);
    // Allowed 0–100 (the manual only proposes 0.001–1, errata DC-20): 150 is refused.
    EXPECT_TRUE(sim.writeMany(7, 0x0090, floatRegisters(2.0f)).ok());
    EXPECT_EQ(sim.writeMany(7, 0x0090, floatRegisters(150.0f)).exception, 0x03);
}

TEST_F(DcPid, PresetStoredByFourRegisters)
{
    ASSERT_TRUE(sim.write(7, "preset.forward_speed", 300).ok());
    powerCycle();
    EXPECT_EQ(sim.readOne(7, "preset.forward_speed"), 500);
    ASSERT_TRUE(sim.writeMany(7, 0x00A0, {0, 1, 300, 400}).ok());
    powerCycle();
    EXPECT_EQ(sim.read(7, 3, 0x00A0, 4).values, (QVector<quint16>{0, 1, 300, 400}));
}

TEST_F(DcPid, GpioStoredByFiveRegisters)
{
    ASSERT_TRUE(sim.writeMany(7, 0x0050, {1, 1, 1, 0}).ok()); // four: temporary
    EXPECT_EQ(sim.read(7, 3, 0x0050, 4).values, (QVector<quint16>{1, 1, 1, 0}));
    powerCycle();
    EXPECT_EQ(sim.read(7, 3, 0x0050, 4).values, (QVector<quint16>{0, 0, 0, 0}));
    ASSERT_TRUE(sim.writeMany(7, 0x0050, {1, 0, 1, 0, 1}).ok());
    powerCycle();
    EXPECT_EQ(sim.read(7, 3, 0x0050, 4).values, (QVector<quint16>{1, 0, 1, 0}));
    EXPECT_EQ(sim.write(7, 0x0054, 1).exception, 0x02); // not accessible alone
}

TEST_F(DcPid, SpeedCommandDrivesTheMotorAndBrakes)
{
    const auto speed = [&] { return sim.raw(7, "status.commutation"); };
    ASSERT_TRUE(sim.write(7, "speed.command", 500).ok()); // 50.0 % duty, applied at once
    sim.advance(20);
    EXPECT_LT(pwm(), 500); // the 10 A current limit holds the duty back while starting
    EXPECT_EQ(sim.readOne(7, "status.current"), sim.readOne(7, "config.max_current"));
    EXPECT_LT(speed(), 200); // the shaft is still accelerating
    sim.advance(400);
    EXPECT_EQ(pwm(), 500);
    EXPECT_NEAR(speed(), 490, 10); // no-load speed at half duty, less friction
    EXPECT_LT(sim.readOne(7, "status.current"), 100);
    ASSERT_TRUE(sim.write(7, "speed.command", 0).ok()); // brake
    sim.advance(20);
    EXPECT_EQ(pwm(), 0);
    sim.advance(400);
    EXPECT_EQ(speed(), 0);
    ASSERT_TRUE(sim.write(7, "speed.command", 0xFC18).ok()); // -1000: reverse, full
    sim.advance(600);
    EXPECT_EQ(pwm(), 1000); // magnitude; the register is unsigned
    EXPECT_NEAR(speed(), 980, 15);
    ASSERT_TRUE(sim.write(7, "speed.release", 1).ok()); // natural stop: slower than braking
    sim.advance(400);
    EXPECT_EQ(pwm(), 0);
    EXPECT_GT(speed(), 500);
    sim.advance(3000);
    EXPECT_EQ(speed(), 0);
}

TEST_F(DcPid, CommunicationLossBrakes)
{
    ASSERT_TRUE(sim.write(7, "config.comm_loss_time", 10).ok()); // 1.0 s
    ASSERT_TRUE(sim.write(7, "speed.command", 500).ok());
    sim.advance(900);
    EXPECT_EQ(sim.readOne(7, "status.pwm"), 500); // this frame also restarts the time
    sim.advance(900);
    EXPECT_EQ(pwm(), 500);
    sim.advance(200);
    EXPECT_LT(pwm(), 500);
    sim.advance(200);
    EXPECT_EQ(pwm(), 0);
}

TEST_F(DcPid, LimitSwitchStopsForwardMotion)
{
    ASSERT_TRUE(sim.write(7, "config.limit_enable", 1).ok());
    ASSERT_TRUE(sim.write(7, "config.sq1_level", 1).ok());
    ASSERT_TRUE(sim.write(7, "config.sq2_level", 1).ok());
    ASSERT_TRUE(sim.write(7, "speed.command", 500).ok());
    sim.advance(300);
    EXPECT_EQ(pwm(), 500);
    ASSERT_TRUE(sim.bus->control(7, {QStringLiteral("input"), QStringLiteral("1")}).ok);
    sim.advance(300);
    EXPECT_EQ(pwm(), 0);
    EXPECT_EQ(sim.readOne(7, "status.sq1_level"), 1);
}

TEST_F(DcPid, BaudChangeTakesEffectAtPowerCycle)
{
    sim.bus->setLine(19200, 'N');
    ASSERT_TRUE(sim.writeMany(7, 0x008A, {0, 9600}).ok());
    ASSERT_TRUE(sim.write(7, "store.config", 1).ok());
    EXPECT_TRUE(sim.read(7, 3, 0x008A, 2).ok()); // still at 19200 until power-on
    powerCycle();
    EXPECT_EQ(sim.device(7)->lineBaud(), 9600);
    EXPECT_FALSE(sim.read(7, 3, 0x008A, 2).replied);
    sim.bus->setLine(9600, 'N');
    EXPECT_EQ(sim.read(7, 3, 0x008A, 2).values, (QVector<quint16>{0, 9600}));
}

TEST_F(DcPid, LockStopsAndTorqueModeSetsTheCurrent)
{
    ASSERT_TRUE(sim.write(7, "speed.command", 800).ok());
    sim.advance(500);
    ASSERT_EQ(pwm(), 800);
    ASSERT_TRUE(sim.write(7, "speed.lock", 300).ok()); // stop and hold at 30 % duty
    sim.advance(200);
    EXPECT_EQ(pwm(), 0);
    EXPECT_EQ(static_cast<DcPidSimDevice*>(sim.device(7))->drive(), DcPidSimDevice::Drive::Locked);
    ASSERT_TRUE(sim.write(7, "config.speed_mode", 1).ok());
    ASSERT_TRUE(sim.write(7, "speed.command", 600).ok()); // 6.00 A while the supply allows it
    sim.advance(20);
    EXPECT_EQ(sim.readOne(7, "status.current"), 600);
    ASSERT_TRUE(sim.write(7, "config.max_current", 400).ok());
    sim.advance(10);
    EXPECT_EQ(sim.readOne(7, "status.current"), 400); // limited by the maximum current
    sim.advance(1000); // unloaded, the motor runs up until the back-EMF leaves little current
    EXPECT_LT(sim.readOne(7, "status.current"), 100);
}
