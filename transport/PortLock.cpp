// What PortLock does the same on every system; the locking itself is PortLock_posix.cpp (flock,
// lock files, exclusive mode) and PortLock_win.cpp (a COM port opens exclusively).
#include "transport/PortLock.h"

#include <QCoreApplication>

namespace opentop {

PortLock::~PortLock()
{
    release();
}

QString PortLock::lockFilePath() const
{
    return m_file ? m_file->createdPath() : QString();
}

QString PortLock::inUseText(const QString& port, const Holder& holder)
{
    if (holder.pid <= 0)
        return QCoreApplication::translate("opentop::Transport",
                                           "%1 is in use by another program; close it first.")
            .arg(port);
    const QString program =
        holder.program.isEmpty()
            ? QCoreApplication::translate("opentop::Transport", "another program")
            : holder.program;
    return QCoreApplication::translate("opentop::Transport",
                                       "%1 is in use by %2 (PID %3); close it first.")
        .arg(port, program)
        .arg(holder.pid);
}

} // namespace opentop
