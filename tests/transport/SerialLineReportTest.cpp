// The line report's one-line text, the latency the scan must allow for, and the warning.
#include "transport/SerialLineReport.h"

#include <gtest/gtest.h>

using namespace opentop;

namespace {

using Direction = SerialLineReport::Direction;
using LowLatency = SerialLineReport::LowLatency;

SerialLineReport report(Direction direction, LowLatency lowLatency)
{
    SerialLineReport r;
    r.direction = direction;
    r.lowLatency = lowLatency;
    return r;
}

} // namespace

TEST(SerialLineReportTest, EmptyForABusWithoutASerialLine)
{
    const SerialLineReport none;
    EXPECT_TRUE(none.isEmpty());
    EXPECT_EQ(none.text(), QString());
    EXPECT_EQ(none.adapterLatencyMs(), 0);
    EXPECT_EQ(none.latencyWarning(), QString());
    EXPECT_FALSE(report(Direction::Adapter, LowLatency::NotUart).isEmpty());
}

TEST(SerialLineReportTest, TextSaysWhatTheDriverTook)
{
    SerialLineReport r = report(Direction::Kernel, LowLatency::On);
    EXPECT_EQ(r.text(), QStringLiteral("RS-485: kernel (RTS high while sending); low latency: on"));
    r.rtsHighWhileSending = false;
    r.rtsDelayBeforeUs = 1000;
    r.rtsDelayAfterUs = 2000;
    EXPECT_EQ(r.directionText(),
              QStringLiteral("RS-485: kernel (RTS low while sending, 1 ms before, 2 ms after)"));

    r = report(Direction::Rts, LowLatency::NotUart);
    r.rtsDelayBeforeUs = r.rtsDelayAfterUs = 520;
    r.kernelRefusal = QStringLiteral("Inappropriate ioctl for device");
    EXPECT_EQ(r.text(), QStringLiteral("RS-485: RTS from the program (RTS high while sending, "
                                       "520 µs before and after; kernel mode refused: "
                                       "Inappropriate ioctl for device); low latency: not a UART, "
                                       "no adapter latency"));

    r = report(Direction::Unavailable, LowLatency::NotApplicable);
    r.kernelRefusal = QStringLiteral("K");
    EXPECT_EQ(r.text(), QStringLiteral("RS-485: kernel mode refused by the driver (K)"));
    r.rtsRefusal = QStringLiteral("R");
    EXPECT_EQ(
        r.text(),
        QStringLiteral("RS-485: not available (kernel mode refused: K; RTS not switchable: R)"));
    r.kernelRefusal.clear();
    EXPECT_EQ(r.text(), QStringLiteral("RS-485: RTS not switchable on this port (R)"));

    r = report(Direction::KernelLeftOn, LowLatency::NotApplicable);
    EXPECT_EQ(r.text(),
              QStringLiteral("RS-485: kernel mode left on by the driver (RTS high while sending)"));
    EXPECT_EQ(report(Direction::Adapter, LowLatency::NotApplicable).text(),
              QStringLiteral("RS-485: switched by the adapter"));
}

TEST(SerialLineReportTest, AdapterLatencyIsWhatTheScanMustAllowFor)
{
    // Nothing to allow for: no adapter, or low latency on.
    EXPECT_EQ(report(Direction::Adapter, LowLatency::NotUart).adapterLatencyMs(), 0);
    SerialLineReport on = report(Direction::Adapter, LowLatency::On);
    on.usbAdapter = true;
    EXPECT_EQ(on.adapterLatencyMs(), 0);
    on.latencyTimerMs = 1;
    EXPECT_EQ(on.adapterLatencyMs(), 0);
    EXPECT_EQ(on.latencyWarning(), QString());
    // The flag took but the timer did not follow: the timer is what the adapter does.
    on.latencyTimerMs = 8;
    EXPECT_EQ(on.adapterLatencyMs(), 8);
    EXPECT_EQ(on.lowLatencyText(), QStringLiteral("low latency: on (but latency timer 8 ms)"));

    // Refused: the latency timer where sysfs has one, else 16 ms for a USB adapter.
    SerialLineReport refused = report(Direction::Adapter, LowLatency::Unavailable);
    EXPECT_EQ(refused.adapterLatencyMs(), 0); // an on-board UART
    refused.usbAdapter = true;
    EXPECT_EQ(refused.adapterLatencyMs(), SerialLineReport::kAssumedUsbLatencyMs);
    EXPECT_EQ(refused.lowLatencyText(),
              QStringLiteral("low latency: not offered by the driver (USB adapter: up to 16 ms "
                             "assumed)"));
    refused.latencyTimerMs = 16;
    refused.latencyTimerPath = QStringLiteral("/sys/class/tty/ttyUSB0/device/latency_timer");
    EXPECT_EQ(refused.adapterLatencyMs(), 16);
    EXPECT_EQ(refused.lowLatencyText(),
              QStringLiteral("low latency: not offered by the driver (latency timer 16 ms)"));
    const QString warning = refused.latencyWarning();
    EXPECT_TRUE(warning.contains(QStringLiteral("up to 16 ms"))) << qPrintable(warning);
    EXPECT_TRUE(warning.contains(QStringLiteral("did not take low latency")))
        << qPrintable(warning);
    EXPECT_TRUE(
        warning.contains(QStringLiteral("echo 1 > /sys/class/tty/ttyUSB0/device/latency_timer")))
        << qPrintable(warning);
    EXPECT_TRUE(warning.contains(QStringLiteral("udev rule"))) << qPrintable(warning);

    // Chosen off.
    SerialLineReport off = report(Direction::Adapter, LowLatency::Off);
    off.usbAdapter = true;
    EXPECT_EQ(off.adapterLatencyMs(), 16);
    EXPECT_TRUE(off.latencyWarning().contains(QStringLiteral("low latency is off")));
    EXPECT_EQ(off.lowLatencyText(), QStringLiteral("low latency: off"));
}
