#include "tests/soak/ProcessProbe.h"

#include <QDir>
#include <QFile>
#include <QString>

namespace opentop::soak {

namespace {

// The number in "Name:   1234 kB" of /proc/PID/status; -1 when the line is missing.
qint64 statusField(const QByteArray& status, const QByteArray& name)
{
    for (const QByteArray& line : status.split('\n')) {
        if (!line.startsWith(name + ':'))
            continue;
        const QList<QByteArray> words = line.mid(name.size() + 1).simplified().split(' ');
        bool ok = false;
        const qint64 value = words.value(0).toLongLong(&ok);
        return ok ? value : -1;
    }
    return -1;
}

} // namespace

ProcessFigures ProcessProbe::read(qint64 pid)
{
    const QString root =
        pid > 0 ? QStringLiteral("/proc/%1").arg(pid) : QStringLiteral("/proc/self");
    ProcessFigures f;
    QFile status(root + QStringLiteral("/status"));
    if (!status.open(QIODevice::ReadOnly))
        return f;
    const QByteArray text = status.readAll();
    f.rssKb = statusField(text, "VmRSS");
    f.threads = int(statusField(text, "Threads"));
    // For this process the count includes the descriptor that reads the directory: the same
    // one every time, so growth is still growth.
    const QDir fdDir(root + QStringLiteral("/fd"));
    if (fdDir.exists())
        f.fds = int(fdDir.entryList(QDir::AllEntries | QDir::System | QDir::NoDotAndDotDot).size());
    return f;
}

} // namespace opentop::soak
