// SerialLineSetup's choices against drivers that take or refuse each request (a fake that
// answers as the kernel does), and the real ioctls on an openpty() pair.
#include "transport/SerialLineSetup.h"
#include "tests/transport/TransportTestSupport.h"
#include "transport/IoctlSerialDriver.h"
#include "transport/ModbusClient.h"
#include "transport/RtuBackend.h"
#include "transport/SerialSysfs.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <cerrno>
#include <gtest/gtest.h>
#include <linux/serial.h>
#include <modbus.h>
#include <pty.h>
#include <unistd.h>

using namespace opentop;

namespace {

using Direction = SerialLineReport::Direction;
using LowLatency = SerialLineReport::LowLatency;
using Rs485 = ConnectionSettings::Rs485;

// A driver that keeps its state like the kernel: TIOCSRS485 may be refused, and what it takes
// may differ from what was asked (`adjust`); the low-latency flag may not stick.
struct FakeDriver : SerialDriver
{
    int rs485GetError = 0;
    int rs485SetError = 0;
    Rs485 rs485;
    std::function<void(Rs485*)> adjust;
    int rtsError = 0;
    bool rtsUsed = false;
    Rts rts;
    int lowLatencyError = 0;
    bool lowLatencySticks = true;
    bool lowLatency = false;
    int rs485Sets = 0;
    int lowLatencySets = 0;

    int getRs485(Rs485* state) override
    {
        if (rs485GetError == 0)
            *state = rs485;
        return rs485GetError;
    }
    int setRs485(Rs485* state) override
    {
        if (rs485SetError != 0)
            return rs485SetError;
        ++rs485Sets;
        if (adjust)
            adjust(state);
        rs485 = *state;
        return 0;
    }
    int useRts(bool high, int delayUs, Rts* readBack) override
    {
        if (rtsError != 0)
            return rtsError;
        rtsUsed = true;
        rts = {high, delayUs > 0 ? delayUs : 520};
        *readBack = rts;
        return 0;
    }
    int getLowLatency(bool* on) override
    {
        if (lowLatencyError == 0)
            *on = lowLatency;
        return lowLatencyError;
    }
    int setLowLatency(bool on) override
    {
        ++lowLatencySets;
        if (lowLatencySticks || !on)
            lowLatency = on;
        return 0;
    }
};

ConnectionSettings line(Rs485 mode)
{
    ConnectionSettings s;
    s.port = QStringLiteral("/dev/ttyS4");
    s.rs485 = mode;
    return s;
}

const SerialSysfs kNoSysfs(QStringLiteral("/dev/ttyS4"), QStringLiteral("/nonexistent"));

} // namespace

TEST(SerialLineSetupTest, KernelModeIsAskedWithPolarityAndDelayAndReadBack)
{
    FakeDriver driver;
    driver.rs485.flags = SER_RS485_RX_DURING_TX; // as found: echo on, RS-485 off
    // The driver clamps the delays it cannot do, as 8250 drivers do.
    driver.adjust = [](SerialDriver::Rs485* s) {
        s->delayBeforeMs = std::min(s->delayBeforeMs, 1u);
    };
    ConnectionSettings s = line(Rs485::Kernel);
    s.rtsHighWhileSending = false;
    s.rtsDelayUs = 1500; // rounded up: 2 ms
    SerialLineSetup setup;
    const SerialLineReport r = setup.apply(driver, s, kNoSysfs);
    EXPECT_EQ(r.direction, Direction::Kernel) << qPrintable(r.text());
    EXPECT_TRUE(driver.rs485.flags & SER_RS485_ENABLED);
    EXPECT_TRUE(driver.rs485.flags & SER_RS485_RTS_AFTER_SEND);
    EXPECT_FALSE(driver.rs485.flags & SER_RS485_RTS_ON_SEND);
    EXPECT_FALSE(driver.rs485.flags & SER_RS485_RX_DURING_TX); // no echo of our requests
    EXPECT_EQ(driver.rs485.delayAfterMs, 2u);
    // What the driver took, not what was asked.
    EXPECT_FALSE(r.rtsHighWhileSending);
    EXPECT_EQ(r.rtsDelayBeforeUs, 1000);
    EXPECT_EQ(r.rtsDelayAfterUs, 2000);
    EXPECT_FALSE(driver.rtsUsed);
    // Closing puts the port back as found.
    setup.restore(driver);
    EXPECT_EQ(driver.rs485.flags, quint32(SER_RS485_RX_DURING_TX));
}

TEST(SerialLineSetupTest, AutoFallsBackToRtsWhenTheKernelRefusesAndSaysWhy)
{
    FakeDriver driver;
    driver.rs485SetError = ENOTTY; // an 8250 without RS-485 support: TIOCGRS485 works, set not
    ConnectionSettings s = line(Rs485::Auto);
    s.rtsDelayUs = 300;
    SerialLineSetup setup;
    SerialLineReport r = setup.apply(driver, s, kNoSysfs);
    EXPECT_EQ(r.direction, Direction::Rts) << qPrintable(r.text());
    EXPECT_TRUE(driver.rtsUsed);
    EXPECT_TRUE(r.rtsHighWhileSending);
    EXPECT_EQ(r.rtsDelayBeforeUs, 300);
    EXPECT_FALSE(r.kernelRefusal.isEmpty());
    EXPECT_TRUE(r.text().contains(QStringLiteral("RTS from the program"))) << qPrintable(r.text());

    // A driver that takes the request but leaves RS-485 off is a refusal too.
    FakeDriver ignoring;
    ignoring.adjust = [](SerialDriver::Rs485* st) { st->flags &= ~quint32(SER_RS485_ENABLED); };
    r = setup.apply(ignoring, s, kNoSysfs);
    EXPECT_EQ(r.direction, Direction::Rts);
    EXPECT_EQ(r.kernelRefusal, QStringLiteral("the driver left it off"));

    // Neither: said, and nothing half set.
    FakeDriver neither;
    neither.rs485GetError = ENOTTY;
    neither.rs485SetError = ENOTTY;
    neither.rtsError = ENOTTY;
    r = setup.apply(neither, s, kNoSysfs);
    EXPECT_EQ(r.direction, Direction::Unavailable);
    EXPECT_TRUE(r.text().startsWith(QStringLiteral("RS-485: not available")))
        << qPrintable(r.text());
}

TEST(SerialLineSetupTest, KernelAndRtsAskedAloneDoNotFallBack)
{
    FakeDriver driver;
    driver.rs485SetError = ENOTTY;
    SerialLineSetup setup;
    SerialLineReport r = setup.apply(driver, line(Rs485::Kernel), kNoSysfs);
    EXPECT_EQ(r.direction, Direction::Unavailable);
    EXPECT_FALSE(driver.rtsUsed);
    EXPECT_TRUE(r.text().contains(QStringLiteral("kernel mode refused"))) << qPrintable(r.text());

    FakeDriver kernelCapable;
    r = setup.apply(kernelCapable, line(Rs485::Rts), kNoSysfs);
    EXPECT_EQ(r.direction, Direction::Rts);
    EXPECT_EQ(kernelCapable.rs485Sets, 0);
}

TEST(SerialLineSetupTest, OffLeavesTheDriverAloneButSaysWhenItsRs485ModeIsOn)
{
    FakeDriver driver;
    SerialLineSetup setup;
    EXPECT_EQ(setup.apply(driver, line(Rs485::Off), kNoSysfs).direction, Direction::Adapter);
    driver.rs485.flags = SER_RS485_ENABLED | SER_RS485_RTS_ON_SEND;
    const SerialLineReport r = setup.apply(driver, line(Rs485::Off), kNoSysfs);
    EXPECT_EQ(r.direction, Direction::KernelLeftOn);
    EXPECT_EQ(driver.rs485Sets, 0);
    EXPECT_FALSE(driver.rtsUsed);
    setup.restore(driver);
    EXPECT_EQ(driver.rs485.flags, quint32(SER_RS485_ENABLED | SER_RS485_RTS_ON_SEND));
}

TEST(SerialLineSetupTest, LowLatencyIsReadBackAndItsRefusalNamesTheLatencyTimer)
{
    QTemporaryDir sys;
    ASSERT_TRUE(sys.isValid());
    const QString device = sys.path() + QStringLiteral("/devices/usb1/1-1/1-1:1.0/ttyUSB9");
    QDir().mkpath(device);
    QDir().mkpath(sys.path() + QStringLiteral("/class/tty/ttyUSB9"));
    ASSERT_TRUE(QFile::link(device, sys.path() + QStringLiteral("/class/tty/ttyUSB9/device")));
    QFile timer(device + QStringLiteral("/latency_timer"));
    ASSERT_TRUE(timer.open(QIODevice::WriteOnly));
    timer.write("16\n");
    timer.close();
    const SerialSysfs usb(QStringLiteral("/dev/ttyUSB9"), sys.path());
    ConnectionSettings s = line(Rs485::Off);
    s.port = QStringLiteral("/dev/ttyUSB9");

    FakeDriver taking;
    SerialLineSetup setup;
    SerialLineReport r = setup.apply(taking, s, kNoSysfs);
    EXPECT_EQ(r.lowLatency, LowLatency::On);
    EXPECT_TRUE(taking.lowLatency);
    setup.restore(taking);
    EXPECT_FALSE(taking.lowLatency); // as found

    FakeDriver stubborn;
    stubborn.lowLatencySticks = false;
    r = setup.apply(stubborn, s, usb);
    EXPECT_EQ(r.lowLatency, LowLatency::Unavailable);
    EXPECT_TRUE(r.usbAdapter);
    EXPECT_EQ(r.latencyTimerMs, 16);
    EXPECT_EQ(r.adapterLatencyMs(), 16);
    EXPECT_EQ(r.lowLatencyText(),
              QStringLiteral("low latency: not offered by the driver (latency timer 16 ms)"));

    // Chosen off: not touched, and the latency it leaves is known.
    s.lowLatency = false;
    FakeDriver untouched;
    r = setup.apply(untouched, s, usb);
    EXPECT_EQ(r.lowLatency, LowLatency::Off);
    EXPECT_EQ(untouched.lowLatencySets, 0);
    EXPECT_EQ(r.adapterLatencyMs(), 16);

    // No UART settings at all on a non-USB tty: not a UART. On a USB adapter: unavailable.
    s.lowLatency = true;
    FakeDriver noUart;
    noUart.lowLatencyError = ENOTTY;
    EXPECT_EQ(setup.apply(noUart, s, kNoSysfs).lowLatency, LowLatency::NotUart);
    r = setup.apply(noUart, s, usb);
    EXPECT_EQ(r.lowLatency, LowLatency::Unavailable);
    EXPECT_EQ(r.adapterLatencyMs(), 16);
}

// The real ioctls on a pty: no RS-485 mode, no modem lines, no UART settings.
TEST(SerialLineSetupTest, OnAPtyKernelIsRefusedRtsIsNotSwitchableAndThereIsNoUart)
{
    int master = -1;
    int slave = -1;
    char name[256] = {};
    ASSERT_EQ(::openpty(&master, &slave, name, nullptr, nullptr), 0);
    modbus_t* ctx = modbus_new_rtu(name, 19200, 'N', 8, 1);
    ASSERT_NE(ctx, nullptr);
    ASSERT_EQ(modbus_connect(ctx), 0);
    IoctlSerialDriver driver(modbus_get_socket(ctx), ctx);
    SerialLineSetup setup;
    ConnectionSettings s = line(Rs485::Auto);
    s.port = QString::fromLocal8Bit(name);
    const SerialSysfs sysfs(s.port);

    SerialLineReport r = setup.apply(driver, s, sysfs);
    EXPECT_EQ(r.direction, Direction::Unavailable) << qPrintable(r.text());
    EXPECT_EQ(r.kernelRefusal, qt_error_string(ENOTTY));
    EXPECT_EQ(r.rtsRefusal, qt_error_string(ENOTTY)); // libmodbus alone would have said yes
    EXPECT_EQ(modbus_rtu_get_rts(ctx), MODBUS_RTU_RTS_NONE);
    EXPECT_EQ(r.lowLatency, LowLatency::NotUart);
    EXPECT_EQ(r.adapterLatencyMs(), 0);
    EXPECT_EQ(r.lowLatencyText(), QStringLiteral("low latency: not a UART, no adapter latency"));

    s.rs485 = Rs485::Off;
    r = setup.apply(driver, s, sysfs);
    EXPECT_EQ(r.text(), QStringLiteral("RS-485: switched by the adapter; low latency: not a UART, "
                                       "no adapter latency"));
    setup.restore(driver);
    modbus_close(ctx);
    modbus_free(ctx);
    ::close(master);
    ::close(slave);
}

// Through the backend and the client, as the programs get it.
TEST(SerialLineSetupTest, TheClientHasTheReportOfItsOpenPort)
{
    test::PtyDevice device;
    device.start([](const QByteArray&) { return test::Answer(); });
    ConnectionSettings s;
    s.port = device.path();
    s.rs485 = Rs485::Kernel;
    ModbusClient client(std::make_unique<RtuBackend>(s), s);
    EXPECT_TRUE(client.lineReport().isEmpty()); // not open yet
    ASSERT_EQ(client.openBlocking(), QString());
    const SerialLineReport r = client.lineReport();
    EXPECT_EQ(r.direction, Direction::Unavailable);
    EXPECT_TRUE(r.text().startsWith(QStringLiteral("RS-485: kernel mode refused by the driver (")))
        << qPrintable(r.text());
    EXPECT_EQ(r.lowLatency, LowLatency::NotUart);
    EXPECT_EQ(client.adapterLatencyMs(), 0);
}
