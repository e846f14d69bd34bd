#pragma once

#include <QString>
#include <QStringList>

namespace opentop {

// The conventional UUCP lock file of a serial device (LCK..ttyUSB0 in /var/lock, which is
// /run/lock on Debian), the way Qt's QSerialPort (QLockFile) and minicom mark a port in use.
// Written in QLockFile's layout ("PID\nprogram\nhost\n"), which the UUCP readers (minicom,
// lockdev: the first number is the PID) read too. The file only names the owner; the device
// lock itself is PortLock's flock, which dies with the process. A file whose process is gone,
// or whose PID now belongs to another program, is stale: it is removed (and logged).
class PortLockFile
{
public:
    // `device` is the canonical device path (/dev/ttyUSB0, /dev/pts/3).
    PortLockFile(const QString& device, const QStringList& directories);
    ~PortLockFile();
    PortLockFile(const PortLockFile&) = delete;
    PortLockFile& operator=(const PortLockFile&) = delete;

    // LCK..ttyUSB0 for /dev/ttyUSB0, LCK..pts_3 for /dev/pts/3 (QSerialPort's naming).
    static QString fileName(const QString& device);
    // $OPENTOP_LOCK_DIR if set, else /var/lock and /run/lock (one directory on Debian).
    static QStringList defaultDirectories();

    struct Owner
    {
        qint64 pid = 0;
        QString program; // as the lock file names it (may be empty)
        QString path;    // the lock file
    };
    enum class Mode
    {
        Inspect, // only reads: names whoever a lock file names, if that process runs
        Claim,   // the caller holds the device lock: removes stale files, and a file naming a
                 // running OpenTOP is stale too (an OpenTOP that holds a port holds its lock)
    };
    // The running owner a lock file names, other than this process.
    bool findOwner(Owner* owner, Mode mode);
    // Creates the lock file for this process in the first usable directory. False (with the
    // reason) when no directory takes it; the caller then relies on the device lock alone.
    bool create(QString* why);
    // Removes the file this object created.
    void remove();
    QString createdPath() const { return m_created; }

    // Program name of a running process (/proc/PID/exe, else comm); empty if unknown.
    static QString programOf(qint64 pid);
    static bool isAlive(qint64 pid);
    static bool isOpenTopProgram(const QString& program);

private:
    QStringList existingDirectories() const;

    QString m_name;
    QStringList m_directories;
    QString m_created;
    int m_fd = -1; // the created file stays open and flock'ed, as QLockFile does
};

} // namespace opentop
