#include "transport/PortLockFile.h"

#include "transport/TransportLog.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSet>
#include <QSysInfo>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace opentop {

namespace {

QString readProcText(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QString::fromLocal8Bit(f.read(4096)).trimmed();
}

// "PID\nprogram\nhost\n" (QLockFile), "      1234\n" (HDB UUCP), "1234 minicom user" (minicom).
bool parse(const QByteArray& text, qint64* pid, QString* program)
{
    const QList<QByteArray> lines = text.split('\n');
    const QList<QByteArray> first = lines.value(0).simplified().split(' ');
    bool ok = false;
    *pid = first.value(0).toLongLong(&ok);
    if (!ok || *pid <= 0)
        return false;
    if (first.size() > 1)
        *program = QString::fromLocal8Bit(first.value(1));
    else
        *program = QString::fromLocal8Bit(lines.value(1).trimmed());
    return true;
}

bool sameProgram(const QString& recorded, const QString& running)
{
    if (recorded.isEmpty() || running.isEmpty())
        return true; // nothing to tell them apart by
    // /proc/PID/comm keeps 15 characters.
    return recorded == running || (running.size() == 15 && recorded.startsWith(running));
}

} // namespace

PortLockFile::PortLockFile(const QString& device, const QStringList& directories)
    : m_name(fileName(device))
    , m_directories(directories)
{
}

PortLockFile::~PortLockFile()
{
    remove();
}

QString PortLockFile::fileName(const QString& device)
{
    QString name = device;
    if (name.startsWith(QLatin1String("/dev/")))
        name = name.mid(5);
    return QStringLiteral("LCK..") + name.replace(QLatin1Char('/'), QLatin1Char('_'));
}

QStringList PortLockFile::defaultDirectories()
{
    const QString custom = qEnvironmentVariable("OPENTOP_LOCK_DIR");
    if (!custom.isEmpty())
        return {custom};
    return {QStringLiteral("/var/lock"), QStringLiteral("/run/lock")};
}

QStringList PortLockFile::existingDirectories() const
{
    QStringList dirs;
    QSet<QString> seen;
    for (const QString& d : m_directories) {
        const QString canonical = QFileInfo(d).canonicalFilePath();
        if (canonical.isEmpty() || !QFileInfo(canonical).isDir() || seen.contains(canonical))
            continue;
        seen.insert(canonical);
        dirs << d;
    }
    return dirs;
}

QString PortLockFile::programOf(qint64 pid)
{
    QString exe = QFile::symLinkTarget(QStringLiteral("/proc/%1/exe").arg(pid));
    if (exe.endsWith(QLatin1String(" (deleted)"))) // replaced on disk since it started
        exe.chop(10);
    if (!exe.isEmpty())
        return QFileInfo(exe).fileName();
    return readProcText(QStringLiteral("/proc/%1/comm").arg(pid));
}

bool PortLockFile::isAlive(qint64 pid)
{
    return pid > 0 && (::kill(pid_t(pid), 0) == 0 || errno == EPERM);
}

bool PortLockFile::isOpenTopProgram(const QString& program)
{
    return program.startsWith(QLatin1String("opentop")) ||
           (!program.isEmpty() && program == programOf(::getpid()));
}

bool PortLockFile::findOwner(Owner* owner, Mode mode)
{
    for (const QString& dir : existingDirectories()) {
        const QString path = dir + QLatin1Char('/') + m_name;
        if (path == m_created)
            continue;
        QFile f(path);
        if (!f.open(QIODevice::ReadOnly))
            continue;
        qint64 pid = 0;
        QString program;
        const bool parsed = parse(f.read(256), &pid, &program);
        f.close();
        QString staleBecause;
        const QString running = parsed ? programOf(pid) : QString();
        if (!parsed)
            staleBecause = QStringLiteral("no PID in it");
        else if (pid == ::getpid())
            staleBecause = QStringLiteral("left by this process");
        else if (!isAlive(pid))
            staleBecause = QStringLiteral("PID %1 is not running").arg(pid);
        else if (!sameProgram(program, running))
            staleBecause =
                QStringLiteral("PID %1 is now %2, not %3").arg(pid).arg(running, program);
        else if (mode == Mode::Claim && isOpenTopProgram(program.isEmpty() ? running : program))
            staleBecause = QStringLiteral("%1 (PID %2) does not hold the port")
                               .arg(program.isEmpty() ? running : program)
                               .arg(pid);
        if (staleBecause.isEmpty()) {
            owner->pid = pid;
            owner->program = program.isEmpty() ? running : program;
            owner->path = path;
            return true;
        }
        if (mode != Mode::Claim)
            continue;
        if (QFile::remove(path))
            qCInfo(lcTransport).noquote()
                << "removed stale lock file" << path << QStringLiteral("(%1)").arg(staleBecause);
        else
            qCWarning(lcTransport).noquote() << "cannot remove stale lock file" << path
                                             << QStringLiteral("(%1)").arg(staleBecause);
    }
    return false;
}

bool PortLockFile::create(QString* why)
{
    remove();
    QStringList reasons;
    const QString self = programOf(::getpid());
    const QByteArray text = QByteArray::number(qint64(::getpid())) + '\n' +
                            (self.isEmpty() ? QByteArray("opentop") : self.toLocal8Bit()) + '\n' +
                            QSysInfo::machineHostName().toLocal8Bit() + '\n';
    const QStringList dirs = existingDirectories();
    if (dirs.isEmpty())
        reasons << QStringLiteral("no directory among %1")
                       .arg(m_directories.join(QStringLiteral(", ")));
    for (const QString& dir : dirs) {
        const QString path = dir + QLatin1Char('/') + m_name;
        const int fd = ::open(QFile::encodeName(path).constData(),
                              O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
        if (fd < 0) {
            reasons << QStringLiteral("%1: %2").arg(path, QString::fromLocal8Bit(strerror(errno)));
            continue;
        }
        ::fchmod(fd, 0644); // readable by everyone whatever the umask
        // Locked like QLockFile's own files, so that Qt programs do not take it for stale.
        (void)::flock(fd, LOCK_EX | LOCK_NB);
        if (::write(fd, text.constData(), size_t(text.size())) != text.size()) {
            reasons << QStringLiteral("%1: %2").arg(path, QString::fromLocal8Bit(strerror(errno)));
            ::close(fd);
            ::unlink(QFile::encodeName(path).constData());
            continue;
        }
        m_fd = fd;
        m_created = path;
        return true;
    }
    if (why)
        *why = reasons.join(QStringLiteral("; "));
    return false;
}

void PortLockFile::remove()
{
    if (m_created.isEmpty())
        return;
    ::unlink(QFile::encodeName(m_created).constData());
    ::close(m_fd);
    m_fd = -1;
    m_created.clear();
}

} // namespace opentop
