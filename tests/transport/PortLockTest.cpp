// PortLock and PortLockFile on an openpty() pair: who is refused, what the refusal says, and
// which lock files are stale. Every test uses its own lock directory.
#include "transport/PortLock.h"
#include "transport/PortLockFile.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QTemporaryDir>
#include <cerrno>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <pty.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <unistd.h>

using namespace opentop;

namespace {

struct Pty
{
    int master = -1;
    int slave = -1;
    QString path;
    Pty()
    {
        char name[256] = {};
        if (::openpty(&master, &slave, name, nullptr, nullptr) != 0)
            throw std::runtime_error("openpty failed");
        path = QString::fromLocal8Bit(name);
    }
    ~Pty()
    {
        ::close(master);
        ::close(slave);
    }
};

QByteArray readFile(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

void writeFile(const QString& path, const QByteArray& text)
{
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write(text);
}

// A process that runs until killed (a program other than an OpenTOP).
struct Sleeper
{
    QProcess process;
    Sleeper(const QStringList& args = {QStringLiteral("sleep"), QStringLiteral("30")})
    {
        process.start(args.first(), args.mid(1));
        process.waitForStarted(5000);
    }
    ~Sleeper()
    {
        process.kill();
        process.waitForFinished(2000);
    }
    qint64 pid() const { return process.processId(); }
};

qint64 deadPid()
{
    QProcess p;
    p.start(QStringLiteral("true"), {});
    p.waitForStarted(5000);
    const qint64 pid = p.processId();
    p.waitForFinished(5000);
    return pid;
}

// Whether /proc/locks lists a lock taken by `pid`.
bool holdsALock(qint64 pid)
{
    QFile locks(QStringLiteral("/proc/locks"));
    return locks.open(QIODevice::ReadOnly) &&
           locks.readAll().contains(" " + QByteArray::number(pid) + " ");
}

QString ownProgram()
{
    return PortLockFile::programOf(::getpid());
}

} // namespace

TEST(PortLockTest, LockFileNamesFollowQSerialPort)
{
    EXPECT_EQ(PortLockFile::fileName(QStringLiteral("/dev/ttyUSB0")),
              QStringLiteral("LCK..ttyUSB0"));
    EXPECT_EQ(PortLockFile::fileName(QStringLiteral("/dev/pts/3")), QStringLiteral("LCK..pts_3"));
    EXPECT_EQ(PortLockFile::fileName(QStringLiteral("/tmp/x/ttyA")),
              QStringLiteral("LCK.._tmp_x_ttyA"));
}

TEST(PortLockTest, SecondLockIsRefusedNamingTheHolderAndTheFirstStaysUsable)
{
    Pty pty;
    QTemporaryDir dir;
    PortLock first(pty.path, {dir.path()});
    QString error;
    ASSERT_EQ(first.acquire(&error), PortLock::Outcome::Acquired) << error.toStdString();
    // The lock file: QLockFile's layout, the PID first (what minicom and lockdev read).
    const QString file = dir.path() + QLatin1Char('/') + PortLockFile::fileName(pty.path);
    EXPECT_EQ(first.lockFilePath(), file);
    const QList<QByteArray> lines = readFile(file).split('\n');
    EXPECT_EQ(lines.value(0).toLongLong(), qint64(::getpid()));
    EXPECT_EQ(QString::fromLocal8Bit(lines.value(1)), ownProgram());

    PortLock second(pty.path, {dir.path()});
    EXPECT_EQ(second.acquire(&error), PortLock::Outcome::InUse);
    EXPECT_EQ(error, QStringLiteral("%1 is in use by %2 (PID %3); close it first.")
                         .arg(pty.path, ownProgram())
                         .arg(::getpid()));
    EXPECT_FALSE(second.isHeld());
    EXPECT_TRUE(QFile::exists(file)) << "the refused one must not remove the holder's file";

    first.release();
    EXPECT_FALSE(QFile::exists(file));
    EXPECT_EQ(second.acquire(&error), PortLock::Outcome::Acquired) << error.toStdString();
}

TEST(PortLockTest, AnotherNameForTheSameDeviceSharesTheLock)
{
    Pty pty;
    QTemporaryDir dir;
    const QString link = dir.filePath(QStringLiteral("ttyLINK"));
    ASSERT_TRUE(QFile::link(pty.path, link));
    PortLock first(pty.path, {dir.path()});
    QString error;
    ASSERT_EQ(first.acquire(&error), PortLock::Outcome::Acquired);
    PortLock second(link, {dir.path()});
    EXPECT_EQ(second.acquire(&error), PortLock::Outcome::InUse);
    EXPECT_TRUE(error.startsWith(link + QStringLiteral(" is in use by "))) << error.toStdString();
}

TEST(PortLockTest, StaleLockFileOfAProcessThatIsGoneIsRemoved)
{
    Pty pty;
    QTemporaryDir dir;
    const QString file = dir.path() + QLatin1Char('/') + PortLockFile::fileName(pty.path);
    const qint64 gone = deadPid();
    writeFile(file, QByteArray::number(gone) + "\nopentop-cli\nhost\n");
    PortLock lock(pty.path, {dir.path()});
    QString error;
    ASSERT_EQ(lock.acquire(&error), PortLock::Outcome::Acquired) << error.toStdString();
    EXPECT_EQ(readFile(file).split('\n').value(0).toLongLong(), qint64(::getpid()));
}

TEST(PortLockTest, LockFileWhosePidIsNowAnotherProgramIsStale)
{
    Pty pty;
    QTemporaryDir dir;
    Sleeper other; // the PID a killed OpenTOP had, now given to `sleep`
    const QString file = dir.path() + QLatin1Char('/') + PortLockFile::fileName(pty.path);
    writeFile(file, QByteArray::number(other.pid()) + "\nopentop-cli\nhost\n");
    PortLock lock(pty.path, {dir.path()});
    QString error;
    EXPECT_EQ(lock.acquire(&error), PortLock::Outcome::Acquired) << error.toStdString();
}

TEST(PortLockTest, LockFileOfAnOpenTopThatDoesNotHoldThePortIsStale)
{
    // A file naming a running OpenTOP while nobody holds the device lock: an OpenTOP that holds
    // a port holds its device lock, so the file is stale (left by a killed one, PID reused).
    Pty pty;
    QTemporaryDir dir;
    const QString fake = dir.filePath(QStringLiteral("opentop-cli"));
    ASSERT_TRUE(QFile::copy(QStringLiteral("/bin/sleep"), fake));
    QFile::setPermissions(fake, QFile::ReadOwner | QFile::ExeOwner);
    Sleeper other({fake, QStringLiteral("30")});
    ASSERT_EQ(PortLockFile::programOf(other.pid()), QStringLiteral("opentop-cli"));
    const QString file = dir.path() + QLatin1Char('/') + PortLockFile::fileName(pty.path);
    writeFile(file, QByteArray::number(other.pid()) + "\nopentop-cli\nhost\n");
    PortLock lock(pty.path, {dir.path()});
    QString error;
    EXPECT_EQ(lock.acquire(&error), PortLock::Outcome::Acquired) << error.toStdString();
    EXPECT_EQ(readFile(file).split('\n').value(0).toLongLong(), qint64(::getpid()));
}

TEST(PortLockTest, LockFileOfAnotherRunningProgramRefusesWithItsName)
{
    Pty pty;
    QTemporaryDir dir;
    Sleeper minicom;
    const QString file = dir.path() + QLatin1Char('/') + PortLockFile::fileName(pty.path);
    PortLock lock(pty.path, {dir.path()});
    QString error;
    // HDB layout (ten-character PID, what minicom writes): the program comes from /proc.
    writeFile(file, QByteArray::number(minicom.pid()).rightJustified(10, ' ') + '\n');
    EXPECT_EQ(lock.acquire(&error), PortLock::Outcome::InUse);
    EXPECT_EQ(error, QStringLiteral("%1 is in use by sleep (PID %2); close it first.")
                         .arg(pty.path)
                         .arg(minicom.pid()));
    // QLockFile layout (a Qt program with QSerialPort).
    writeFile(file, QByteArray::number(minicom.pid()) + "\nsleep\nhost\n");
    EXPECT_EQ(lock.acquire(&error), PortLock::Outcome::InUse);
    EXPECT_TRUE(error.contains(QStringLiteral("sleep (PID %1)").arg(minicom.pid())));
    EXPECT_TRUE(QFile::exists(file));
    EXPECT_FALSE(lock.isHeld());
}

TEST(PortLockTest, DeviceLockHolderIsFoundWithoutALockFile)
{
    // util-linux flock(1) holds flock on the device and names no lock file: /proc/locks does.
    Pty pty;
    QTemporaryDir dir;
    Sleeper holder({QStringLiteral("flock"), QStringLiteral("--nonblock"), pty.path,
                    QStringLiteral("sleep"), QStringLiteral("30")});
    for (int i = 0; i < 250 && !holdsALock(holder.pid()); ++i)
        ::usleep(20000); // flock(1) is still starting
    PortLock lock(pty.path, {dir.path()});
    QString error;
    const PortLock::Outcome outcome = lock.acquire(&error);
    EXPECT_EQ(outcome, PortLock::Outcome::InUse);
    EXPECT_EQ(error, QStringLiteral("%1 is in use by flock (PID %2); close it first.")
                         .arg(pty.path)
                         .arg(holder.pid()));
    EXPECT_TRUE(QDir(dir.path()).entryList(QDir::Files).isEmpty());
}

TEST(PortLockTest, UnusableLockDirectoryFallsBackToTheDeviceLock)
{
    Pty pty;
    QTemporaryDir dir;
    const QString notADirectory = dir.filePath(QStringLiteral("plain-file"));
    writeFile(notADirectory, "x");
    for (const QString& lockDir : {notADirectory, dir.filePath(QStringLiteral("missing"))}) {
        PortLock first(pty.path, {lockDir});
        QString error;
        ASSERT_EQ(first.acquire(&error), PortLock::Outcome::Acquired) << error.toStdString();
        EXPECT_TRUE(first.lockFilePath().isEmpty());
        PortLock second(pty.path, {lockDir});
        EXPECT_EQ(second.acquire(&error), PortLock::Outcome::InUse);
        EXPECT_TRUE(error.contains(QStringLiteral("(PID %1)").arg(::getpid())))
            << error.toStdString();
    }
    if (::geteuid() != 0) { // root writes anywhere
        QTemporaryDir readOnly;
        QFile::setPermissions(readOnly.path(), QFile::ReadOwner | QFile::ExeOwner);
        PortLock lock(pty.path, {readOnly.path()});
        QString error;
        EXPECT_EQ(lock.acquire(&error), PortLock::Outcome::Acquired) << error.toStdString();
        EXPECT_TRUE(lock.lockFilePath().isEmpty());
        QFile::setPermissions(readOnly.path(),
                              QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
    }
}

TEST(PortLockTest, ExclusiveModeIsLeftOffOnPseudoTerminals)
{
    // The pty's server keeps the slave open: exclusive mode would outlive a killed OpenTOP
    // and lock the next one out (the flag ends only with the last close).
    Pty pty;
    QTemporaryDir dir;
    PortLock lock(pty.path, {dir.path()});
    QString error;
    ASSERT_EQ(lock.acquire(&error), PortLock::Outcome::Acquired);
    const int fd = ::open(QFile::encodeName(pty.path).constData(), O_RDWR | O_NOCTTY);
    ASSERT_GE(fd, 0);
    EXPECT_FALSE(PortLock::wantsExclusive(fd));
    lock.makeExclusive(fd);
    int exclusive = -1;
    ASSERT_EQ(::ioctl(fd, TIOCGEXCL, &exclusive), 0);
    EXPECT_EQ(exclusive, 0);
    ::close(fd);
    // Not a character device at all: nothing to make exclusive.
    QFile plain(dir.filePath(QStringLiteral("plain")));
    ASSERT_TRUE(plain.open(QIODevice::WriteOnly));
    EXPECT_FALSE(PortLock::wantsExclusive(plain.handle()));
}

TEST(PortLockTest, ExclusiveModeIsSetOnOtherCharacterDevices)
{
    // A character device other than a pty (/dev/ttyS0, a USB adapter) gets exclusive mode;
    // read back through TIOCGEXCL, so that this holds for root too. /dev/ptmx stands in for it
    // (major 5, opening it makes a new pty master: nothing is disturbed).
    const int fd = ::open("/dev/ptmx", O_RDWR | O_NOCTTY);
    if (fd < 0)
        GTEST_SKIP() << "no /dev/ptmx";
    EXPECT_TRUE(PortLock::wantsExclusive(fd));
    PortLock lock(QStringLiteral("/dev/ptmx"), {});
    lock.makeExclusive(fd);
    int exclusive = -1;
    ASSERT_EQ(::ioctl(fd, TIOCGEXCL, &exclusive), 0);
    EXPECT_EQ(exclusive, 1);
    ::close(fd);
}

TEST(PortLockTest, MissingDeviceIsLeftToTheCallersOpen)
{
    QTemporaryDir dir;
    PortLock lock(QStringLiteral("/dev/opentop-no-such-port"), {dir.path()});
    QString error;
    EXPECT_EQ(lock.acquire(&error), PortLock::Outcome::OpenFailed);
    EXPECT_TRUE(QDir(dir.path()).entryList(QDir::Files).isEmpty());
}
