#pragma once

#include "transport/PortLockFile.h"

#include <QString>
#include <QStringList>
#include <memory>

namespace opentop {

// Keeps a second program off a serial port OpenTOP uses, and tells the user who holds a port
// OpenTOP cannot have. Taken before the port is opened for Modbus, so a refused start changes
// nothing on the line (no termios change, no flush, no frame):
//  1. opens the device itself and takes flock(LOCK_EX | LOCK_NB) on it: the lock goes with the
//     process, so a killed OpenTOP never blocks the next one;
//  2. looks for a UUCP lock file (PortLockFile) naming a running program (minicom, a Qt
//     program, ...): refused; stale files are removed; then writes its own;
//  3. after the port is open, exclusive mode (TIOCEXCL): other opens fail with EBUSY (not for
//     root, whom the kernel lets through). Not on pseudo-terminals: their server keeps the slave
//     open, so the flag would outlive a killed OpenTOP (it ends with the device's last close).
// A refusal names the holder where the system tells it: the lock file's PID and program, else
// the flock's owner from /proc/locks, else a process with the device open (/proc/PID/fd).
// A lock directory that cannot be written is no reason to refuse: the flock alone is used
// (logged). Not thread-safe; one per open port. On Windows (PortLock_win.cpp) a COM port opens
// exclusively: acquire() refuses a port another program has open, and holds a named mutex
// for the port (what flock is here) for drivers that let a port be opened twice.
class PortLock
{
public:
    enum class Outcome
    {
        Acquired,   // ours until release()
        InUse,      // refused; the error names the holder where known
        OpenFailed, // the device cannot be opened at all (ENOENT, EACCES): the caller's own
                    // open will fail and explain it
    };

    explicit PortLock(const QString& port,
                      const QStringList& lockDirectories = PortLockFile::defaultDirectories());
    ~PortLock();
    PortLock(const PortLock&) = delete;
    PortLock& operator=(const PortLock&) = delete;

    Outcome acquire(QString* error);
    // Exclusive mode on the descriptor the port is used through (after acquire()).
    void makeExclusive(int fd);
    // Whether makeExclusive() sets exclusive mode on `fd`: a character device but not a pty.
    static bool wantsExclusive(int fd);
    void release();
    bool isHeld() const; // PortLock_posix.cpp, PortLock_win.cpp
    QString device() const { return m_device; }
    // The lock file written for this port; empty when none could be (flock only).
    QString lockFilePath() const;

    struct Holder
    {
        qint64 pid = 0; // 0: not known
        QString program;
    };
    // Who holds `device` (canonical path): lock file, /proc/locks, then open descriptors.
    static Holder findHolder(const QString& device, const QStringList& lockDirectories);
    // "/dev/ttyUSB0 is in use by minicom (PID 1234); close it first."
    static QString inUseText(const QString& port, const Holder& holder);

private:
    static qint64 flockOwner(const QString& device);
    static qint64 openedBy(const QString& device);

    QString m_port;
    QString m_device;
    QStringList m_directories;
    int m_fd = -1;
    std::unique_ptr<PortLockFile> m_file;
#ifdef Q_OS_WIN
    void* m_mutex = nullptr; // the named mutex that marks the port as an OpenTOP's
#endif
};

} // namespace opentop
