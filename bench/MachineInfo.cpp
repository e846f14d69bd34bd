#include "bench/MachineInfo.h"

#include "transport/LibraryVersions.h"

#include <QFile>
#include <QSysInfo>
#include <QThread>

namespace opentop {

QString MachineInfo::cpuModel()
{
    QFile file(QStringLiteral("/proc/cpuinfo"));
    if (!file.open(QIODevice::ReadOnly))
        return QStringLiteral("unknown CPU");
    for (const QByteArray& line : file.readAll().split('\n')) {
        if (line.startsWith("model name")) {
            const int colon = line.indexOf(':');
            return QString::fromUtf8(line.mid(colon + 1)).simplified();
        }
    }
    return QStringLiteral("unknown CPU");
}

int MachineInfo::cores()
{
    return QThread::idealThreadCount();
}

double MachineInfo::loadAverage()
{
    QFile file(QStringLiteral("/proc/loadavg"));
    if (!file.open(QIODevice::ReadOnly))
        return -1;
    return file.readAll().split(' ').value(0).toDouble();
}

QString MachineInfo::describe()
{
    return QStringLiteral("%1, %2 cores, %3 %4, Qt %5, libmodbus %6; load average %7")
        .arg(cpuModel())
        .arg(cores())
        .arg(QSysInfo::kernelType(), QSysInfo::kernelVersion(), QString::fromLatin1(qVersion()),
             LibraryVersions::libmodbus())
        .arg(loadAverage(), 0, 'f', 2);
}

} // namespace opentop
