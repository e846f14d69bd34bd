// PortLock on POSIX: flock on the device, UUCP lock files, exclusive mode (see PortLock.h).
#include "transport/PortLock.h"

#include "transport/TransportLog.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <termios.h>
#include <unistd.h>

namespace opentop {

namespace {

QString canonicalDevice(const QString& port)
{
    const QString canonical = QFileInfo(port).canonicalFilePath();
    return canonical.isEmpty() ? port : canonical;
}

QString errnoString(int err)
{
    return QString::fromLocal8Bit(strerror(err));
}

} // namespace

PortLock::PortLock(const QString& port, const QStringList& lockDirectories)
    : m_port(port)
    , m_device(canonicalDevice(port))
    , m_directories(lockDirectories)
{
}

PortLock::Outcome PortLock::acquire(QString* error)
{
    release();
    m_device = canonicalDevice(m_port);
    // A running program that is not an OpenTOP and left its lock file (minicom, a Qt program):
    // the port is not even opened.
    PortLockFile::Owner owner;
    if (PortLockFile(m_device, m_directories).findOwner(&owner, PortLockFile::Mode::Inspect) &&
        !PortLockFile::isOpenTopProgram(owner.program)) {
        if (error)
            *error = inUseText(m_port, {owner.pid, owner.program});
        qCWarning(lcTransport).noquote() << m_port << "refused: lock file" << owner.path;
        return Outcome::InUse;
    }
    const int fd =
        ::open(QFile::encodeName(m_device).constData(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        const int err = errno;
        if (err != EBUSY) // the caller's own open reports it, with its advice
            return Outcome::OpenFailed;
        if (error)
            *error = inUseText(m_port, findHolder(m_device, m_directories));
        qCWarning(lcTransport).noquote() << m_port << "refused: exclusive (EBUSY)";
        return Outcome::InUse;
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
        const int err = errno;
        if (err == EWOULDBLOCK) {
            ::close(fd);
            if (error)
                *error = inUseText(m_port, findHolder(m_device, m_directories));
            qCWarning(lcTransport).noquote() << m_port << "refused: locked (flock)";
            return Outcome::InUse;
        }
        qCWarning(lcTransport).noquote()
            << "cannot lock" << m_device
            << QStringLiteral("(%1); relying on the lock file").arg(errnoString(err));
    }
    m_fd = fd;
    m_file = std::make_unique<PortLockFile>(m_device, m_directories);
    if (m_file->findOwner(&owner, PortLockFile::Mode::Claim)) {
        release();
        if (error)
            *error = inUseText(m_port, {owner.pid, owner.program});
        qCWarning(lcTransport).noquote() << m_port << "refused: lock file" << owner.path;
        return Outcome::InUse;
    }
    QString why;
    if (m_file->create(&why))
        qCDebug(lcTransport).noquote() << "locked" << m_device << "with" << m_file->createdPath();
    else
        qCWarning(lcTransport).noquote()
            << "no lock file for" << m_device
            << QStringLiteral("(%1); relying on the device lock (flock) only: programs that look "
                              "only at lock files will not see the port in use")
                   .arg(why);
    return Outcome::Acquired;
}

bool PortLock::wantsExclusive(int fd)
{
    // Unix98 pty slaves (/dev/pts/N) have majors 136-143. The program serving one (opentop-sim,
    // socat) keeps the slave open, so exclusive mode would outlive a killed OpenTOP there and
    // lock every later one out (the flag only ends with the device's last close).
    struct stat st = {};
    if (::fstat(fd, &st) != 0 || !S_ISCHR(st.st_mode))
        return false;
    return major(st.st_rdev) < 136 || major(st.st_rdev) > 143;
}

void PortLock::makeExclusive(int fd)
{
    if (fd < 0)
        return;
    if (!wantsExclusive(fd)) {
        qCDebug(lcTransport).noquote() << "no exclusive mode on the pseudo-terminal" << m_device;
        return;
    }
    if (::ioctl(fd, TIOCEXCL) != 0)
        qCDebug(lcTransport).noquote()
            << "no exclusive mode on" << m_device << QStringLiteral("(%1)").arg(errnoString(errno));
}

bool PortLock::isHeld() const
{
    return m_fd >= 0;
}

void PortLock::release()
{
    if (m_fd < 0)
        return;
    (void)::ioctl(m_fd, TIOCNXCL);
    m_file.reset(); // removes our lock file
    ::close(m_fd);  // and with the last descriptor goes the flock
    m_fd = -1;
}

PortLock::Holder PortLock::findHolder(const QString& device, const QStringList& lockDirectories)
{
    PortLockFile::Owner owner;
    if (PortLockFile(device, lockDirectories).findOwner(&owner, PortLockFile::Mode::Inspect))
        return {owner.pid, owner.program};
    qint64 pid = flockOwner(device);
    if (pid <= 0)
        pid = openedBy(device);
    if (pid <= 0)
        return {};
    return {pid, PortLockFile::programOf(pid)};
}

qint64 PortLock::flockOwner(const QString& device)
{
    struct stat st = {};
    if (::stat(QFile::encodeName(device).constData(), &st) != 0)
        return 0;
    QFile locks(QStringLiteral("/proc/locks"));
    if (!locks.open(QIODevice::ReadOnly))
        return 0;
    // "1: FLOCK  ADVISORY  WRITE 1234 00:05:1028 0 EOF"; waiters ("1: -> FLOCK ...") skipped.
    for (const QByteArray& line : locks.readAll().split('\n')) {
        const QList<QByteArray> f = line.simplified().split(' ');
        if (f.size() < 6 || f.value(1) == "->")
            continue;
        const QList<QByteArray> id = f.value(5).split(':');
        bool okMajor = false, okMinor = false, okInode = false;
        const uint maj = id.value(0).toUInt(&okMajor, 16);
        const uint mnr = id.value(1).toUInt(&okMinor, 16);
        const qulonglong inode = id.value(2).toULongLong(&okInode);
        if (!okMajor || !okMinor || !okInode || maj != major(st.st_dev) ||
            mnr != minor(st.st_dev) || inode != qulonglong(st.st_ino))
            continue;
        const qint64 pid = f.value(4).toLongLong();
        if (pid > 0)
            return pid;
    }
    return 0;
}

qint64 PortLock::openedBy(const QString& device)
{
    const QString self = QString::number(::getpid());
    const QStringList pids =
        QDir(QStringLiteral("/proc")).entryList(QDir::Dirs | QDir::NoDotAndDotDot);
    for (const QString& pid : pids) {
        bool numeric = false;
        const qint64 n = pid.toLongLong(&numeric);
        if (!numeric || pid == self)
            continue;
        const QString fdDir = QStringLiteral("/proc/") + pid + QStringLiteral("/fd");
        for (const QString& fd : QDir(fdDir).entryList(QDir::System | QDir::NoDotAndDotDot)) {
            if (QFile::symLinkTarget(fdDir + QLatin1Char('/') + fd) == device)
                return n;
        }
    }
    return 0;
}

} // namespace opentop
