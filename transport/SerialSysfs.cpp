#include "transport/SerialSysfs.h"

#include <QFile>
#include <QFileInfo>

namespace opentop {

SerialSysfs::SerialSysfs(const QString& port, const QString& root)
    : m_root(root)
{
    // udev's by-id and by-path names, and links made by hand, point at the kernel's name.
    const QString canonical = QFileInfo(port).canonicalFilePath();
    m_tty = QFileInfo(canonical.isEmpty() ? port : canonical).fileName();
}

QString SerialSysfs::deviceDir() const
{
    return m_root + QStringLiteral("/class/tty/") + m_tty + QStringLiteral("/device");
}

bool SerialSysfs::isUsb() const
{
    if (m_tty.isEmpty())
        return false;
    // The device link resolves into the USB tree: /sys/devices/pci.../usb1/1-1/1-1:1.0/ttyUSB0.
    const QString device = QFileInfo(deviceDir()).canonicalFilePath();
    return device.contains(QStringLiteral("/usb"));
}

QString SerialSysfs::latencyTimerPath() const
{
    if (m_tty.isEmpty())
        return QString();
    const QString path = deviceDir() + QStringLiteral("/latency_timer");
    return QFileInfo::exists(path) ? path : QString();
}

int SerialSysfs::latencyTimerMs() const
{
    const QString path = latencyTimerPath();
    if (path.isEmpty())
        return -1;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return -1;
    bool ok = false;
    const int ms = file.readAll().trimmed().toInt(&ok);
    return ok && ms >= 0 ? ms : -1;
}

} // namespace opentop
