// Which port is a USB adapter and its latency timer, on a fake sysfs tree laid out as the
// kernel's (class/tty/NAME/device -> the device in the USB tree).
#include "transport/SerialSysfs.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

void write(const QString& path, const QByteArray& text)
{
    QDir().mkpath(QFileInfo(path).path());
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly)) << qPrintable(path);
    file.write(text);
}

// class/tty/NAME/device -> devices/...DEVICE, as a relative link like the kernel's.
void addTty(const QString& root, const QString& name, const QString& device)
{
    const QString ttyDir = root + QStringLiteral("/class/tty/") + name;
    QDir().mkpath(ttyDir);
    QDir().mkpath(root + QStringLiteral("/devices/") + device);
    ASSERT_TRUE(QFile::link(QStringLiteral("../../../devices/") + device,
                            ttyDir + QStringLiteral("/device")));
}

} // namespace

TEST(SerialSysfsTest, AnFtdiAdapterReachedThroughASymlinkHasItsLatencyTimer)
{
    QTemporaryDir sys;
    QTemporaryDir dev;
    ASSERT_TRUE(sys.isValid() && dev.isValid());
    addTty(sys.path(), QStringLiteral("ttyUSB3"),
           QStringLiteral("pci0000:00/0000:00:14.0/usb1/1-2/1-2:1.0/ttyUSB3"));
    write(sys.path() + QStringLiteral("/devices/pci0000:00/0000:00:14.0/usb1/1-2/1-2:1.0/ttyUSB3/"
                                      "latency_timer"),
          "16\n");
    // /dev/serial/by-id/usb-FTDI_...-if00-port0 -> ../../ttyUSB3
    write(dev.filePath(QStringLiteral("ttyUSB3")), "");
    const QString byId = dev.filePath(QStringLiteral("usb-FTDI_FT232R_USB_UART_A1-if00-port0"));
    ASSERT_TRUE(QFile::link(dev.filePath(QStringLiteral("ttyUSB3")), byId));

    const SerialSysfs port(byId, sys.path());
    EXPECT_EQ(port.ttyName(), QStringLiteral("ttyUSB3"));
    EXPECT_TRUE(port.isUsb());
    EXPECT_EQ(port.latencyTimerPath(),
              sys.path() + QStringLiteral("/class/tty/ttyUSB3/device/latency_timer"));
    EXPECT_EQ(port.latencyTimerMs(), 16);
}

TEST(SerialSysfsTest, AnOnBoardUartAndAPtyHaveNoLatencyTimer)
{
    QTemporaryDir sys;
    ASSERT_TRUE(sys.isValid());
    addTty(sys.path(), QStringLiteral("ttyS1"), QStringLiteral("platform/serial8250/ttyS1"));
    const SerialSysfs uart(QStringLiteral("/dev/ttyS1"), sys.path());
    EXPECT_EQ(uart.ttyName(), QStringLiteral("ttyS1"));
    EXPECT_FALSE(uart.isUsb());
    EXPECT_EQ(uart.latencyTimerPath(), QString());
    EXPECT_EQ(uart.latencyTimerMs(), -1);

    const SerialSysfs pty(QStringLiteral("/dev/pts/7"), sys.path());
    EXPECT_FALSE(pty.isUsb());
    EXPECT_EQ(pty.latencyTimerMs(), -1);

    // A CH340 or CP210x: USB, but no latency timer.
    addTty(sys.path(), QStringLiteral("ttyUSB0"),
           QStringLiteral("pci0000:00/usb2/2-1/2-1:1.0/ttyUSB0"));
    const SerialSysfs ch340(QStringLiteral("/dev/ttyUSB0"), sys.path());
    EXPECT_TRUE(ch340.isUsb());
    EXPECT_EQ(ch340.latencyTimerMs(), -1);
}
