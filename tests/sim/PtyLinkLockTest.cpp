// Two simulators on one --pty link (issue 28, item 7): the link is locked ("<link>.lock",
// QLockFile) while a simulator serves it, so a second one is refused naming the holder's PID and
// the link keeps pointing at the first one's pty; a lock whose holder is gone (a killed
// simulator) is taken over at once, whatever pty the old link pointed at. The real programs,
// killed with SIGKILL, are in tests/e2e/SimPtyLockE2eTest.cpp.
#include "tests/sim/SimTestSupport.h"

#include "sim/PtySimServer.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <sys/wait.h>
#include <unistd.h>

using namespace opentop;
using namespace opentop::test;

namespace {

class PtyLinkLock : public ::testing::Test
{
protected:
    void SetUp() override
    {
        QString error;
        bus = SimBus::fromSpec(QStringLiteral("dbu200@1"), &error);
        ASSERT_TRUE(bus) << error.toStdString();
        ASSERT_TRUE(dir.isValid());
        link = dir.filePath(QStringLiteral("ttySIM"));
    }

    // The PID the lock file names (its first line), 0 when there is none.
    qint64 lockHolder() const
    {
        QFile file(link + QStringLiteral(".lock"));
        if (!file.open(QIODevice::ReadOnly))
            return 0;
        return file.readLine().trimmed().toLongLong();
    }

    std::shared_ptr<SimBus> bus;
    QTemporaryDir dir;
    QString link;
};

// A PID that no process has any more: a child that has exited and been reaped.
qint64 deadPid()
{
    const pid_t child = ::fork();
    if (child == 0)
        ::_exit(0);
    int status = 0;
    ::waitpid(child, &status, 0);
    return child;
}

} // namespace

TEST_F(PtyLinkLock, ASecondServerOnALinkInUseIsRefusedNamingTheHolder)
{
    PtySimServer first(bus, WireTiming(), false);
    QString error;
    ASSERT_TRUE(first.open(link, &error)) << error.toStdString();
    EXPECT_EQ(lockHolder(), QCoreApplication::applicationPid());

    PtySimServer second(bus, WireTiming(), false);
    EXPECT_FALSE(second.open(link, &error));
    EXPECT_EQ(error, QStringLiteral("%1 is in use by another simulator (PID %2); stop it first, or "
                                    "choose another path for --pty")
                         .arg(link)
                         .arg(QCoreApplication::applicationPid()));
    EXPECT_EQ(second.linkHolderPid(), QCoreApplication::applicationPid());
    EXPECT_FALSE(second.isOpen());
    // The first one's users keep their line.
    EXPECT_EQ(QFileInfo(link).symLinkTarget(), first.slavePath());
    EXPECT_EQ(lockHolder(), QCoreApplication::applicationPid());

    // Closed, the first one removes its link and its lock: the link is free again.
    first.close();
    EXPECT_FALSE(QFileInfo(link).isSymLink());
    EXPECT_FALSE(QFileInfo::exists(link + QStringLiteral(".lock")));
    ASSERT_TRUE(second.open(link, &error)) << error.toStdString();
    EXPECT_EQ(second.linkHolderPid(), 0);
    EXPECT_EQ(QFileInfo(link).symLinkTarget(), second.slavePath());
}

TEST_F(PtyLinkLock, ALinkLeftByASimulatorThatIsGoneIsTakenOver)
{
    // What a SIGKILLed simulator leaves: its link, and a lock naming a PID that no longer runs
    // (QLockFile's layout: PID, program, host). The link may even point at a pty that exists
    // again: the lock alone decides.
    PtySimServer other(bus, WireTiming(), false);
    QString error;
    ASSERT_TRUE(other.open(QString(), &error)) << error.toStdString();
    ASSERT_TRUE(QFile::link(other.slavePath(), link));
    const qint64 gone = deadPid();
    QFile lock(link + QStringLiteral(".lock"));
    ASSERT_TRUE(lock.open(QIODevice::WriteOnly));
    lock.write(QByteArray::number(gone) + "\nopentop-sim\n\n");
    lock.close();

    PtySimServer server(bus, WireTiming(), false);
    ASSERT_TRUE(server.open(link, &error)) << error.toStdString();
    EXPECT_EQ(server.linkHolderPid(), 0);
    EXPECT_EQ(QFileInfo(link).symLinkTarget(), server.slavePath());
    EXPECT_EQ(lockHolder(), QCoreApplication::applicationPid());
}

TEST_F(PtyLinkLock, AnUnpluggedSimulatorKeepsItsLink)
{
    PtySimServer first(bus, WireTiming(), false);
    QString error;
    ASSERT_TRUE(first.open(link, &error)) << error.toStdString();
    first.unplug();
    EXPECT_FALSE(QFileInfo(link).isSymLink());
    // The adapter is out, but the simulator will plug it in again: nobody else takes the link.
    PtySimServer second(bus, WireTiming(), false);
    EXPECT_FALSE(second.open(link, &error));
    EXPECT_EQ(second.linkHolderPid(), QCoreApplication::applicationPid());
    ASSERT_TRUE(first.replug(&error)) << error.toStdString();
    EXPECT_EQ(QFileInfo(link).symLinkTarget(), first.slavePath());
    first.close();
    EXPECT_FALSE(QFileInfo::exists(link + QStringLiteral(".lock")));
}

TEST_F(PtyLinkLock, ARefusedLinkIsNotLocked)
{
    // A regular file where the link should be: refused, and no lock is left behind for it.
    QFile regular(link);
    ASSERT_TRUE(regular.open(QIODevice::WriteOnly));
    regular.close();
    PtySimServer server(bus, WireTiming(), false);
    QString error;
    EXPECT_FALSE(server.open(link, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("not a symlink"))) << error.toStdString();
    EXPECT_EQ(server.linkHolderPid(), 0);
    EXPECT_FALSE(QFileInfo::exists(link + QStringLiteral(".lock")));
}
