#pragma once

#include <QString>

namespace opentop {

// What sysfs says about a serial port: whether it is a USB adapter and its latency timer
// (FTDI's latency_timer: how long the chip holds received bytes, 16 ms by default). `root` is
// "/sys" except in tests.
class SerialSysfs
{
public:
    explicit SerialSysfs(const QString& port, const QString& root = QStringLiteral("/sys"));

    // "ttyUSB0" for /dev/ttyUSB0 and for a symlink to it (/dev/serial/by-id/...).
    QString ttyName() const { return m_tty; }
    bool isUsb() const;
    // The latency_timer file, empty when the driver has none.
    QString latencyTimerPath() const;
    // -1 when there is no latency timer or it cannot be read.
    int latencyTimerMs() const;

private:
    QString deviceDir() const;

    QString m_tty;
    QString m_root;
};

} // namespace opentop
