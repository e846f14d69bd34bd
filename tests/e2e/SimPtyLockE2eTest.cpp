// Two opentop-sim programs on one --pty link (issue 28, item 7): the second is refused (exit 2,
// naming the link and the first one's PID) and the first keeps serving behind the link; a
// simulator killed with SIGKILL leaves its link and lock behind, and the next one on the link
// takes both over at once (as MainWindowLinkLossTest's restarted simulator does). Real
// processes; opentop-cli scans through the link.
#include "tests/e2e/CliProcess.h"
#include "tests/e2e/SimProcess.h"

#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QTemporaryDir>
#include <memory>

using namespace opentop::test;

namespace {

bool startOn(SimProcess& sim, const QString& link, const QString& devices)
{
    QString error;
    const bool ok =
        sim.start({QStringLiteral("--devices"), devices, QStringLiteral("--pty"), link}, &error);
    EXPECT_TRUE(ok) << error.toStdString();
    return ok;
}

// The scan row of machine number 1 through `link`, or what went wrong.
QString scanRow(const QString& link)
{
    const CliResult r = scanOn(link, 1, 1);
    if (r.code != 0)
        return QStringLiteral("exit %1: %2").arg(r.code).arg(r.err);
    for (const QString& line : r.out.split(QLatin1Char('\n'))) {
        if (line.trimmed().startsWith(QStringLiteral("1 ")))
            return line.simplified();
    }
    return QStringLiteral("no row for 1 in: ") + r.out;
}

qint64 lockHolder(const QString& link)
{
    QFile file(link + QStringLiteral(".lock"));
    if (!file.open(QIODevice::ReadOnly))
        return 0;
    return file.readLine().trimmed().toLongLong();
}

} // namespace

TEST(SimPtyLockE2e, ASecondSimulatorOnALinkInUseIsRefusedAndTheFirstKeepsServing)
{
    QTemporaryDir dir;
    const QString link = dir.filePath(QStringLiteral("ttyBUS"));
    SimProcess first;
    ASSERT_TRUE(startOn(first, link, QStringLiteral("dbu200@1")));
    const qint64 holder = first.process().processId();
    EXPECT_EQ(lockHolder(link), holder);

    QProcess second;
    second.start(SimProcess::program(), {QStringLiteral("--devices"), QStringLiteral("dcpid@1"),
                                         QStringLiteral("--pty"), link, QStringLiteral("--quiet")});
    ASSERT_TRUE(second.waitForFinished(10000));
    EXPECT_EQ(second.exitStatus(), QProcess::NormalExit);
    EXPECT_EQ(second.exitCode(), 2);
    EXPECT_EQ(QString::fromLocal8Bit(second.readAllStandardError()).trimmed(),
              QStringLiteral("opentop-sim: %1 is in use by another simulator (PID %2); stop it "
                             "first, or choose another path for --pty")
                  .arg(link)
                  .arg(holder));
    EXPECT_FALSE(second.readAllStandardOutput().contains("ready"));

    // The link still leads to the first simulator's DBU, not to the second one's DC controller.
    EXPECT_EQ(QFileInfo(link).symLinkTarget(), first.pty);
    const QString row = scanRow(link);
    EXPECT_TRUE(row.contains(QStringLiteral(" dbu ")) && row.endsWith(QStringLiteral("online")))
        << row.toStdString();
    EXPECT_EQ(lockHolder(link), holder);

    // Stopped cleanly, the first one removes its link and lock.
    EXPECT_EQ(first.terminate(), 0);
    EXPECT_FALSE(QFileInfo(link).isSymLink());
    EXPECT_FALSE(QFileInfo::exists(link + QStringLiteral(".lock")));
}

TEST(SimPtyLockE2e, TheLinkOfAKilledSimulatorIsTakenOverByTheNextOne)
{
    QTemporaryDir dir;
    const QString link = dir.filePath(QStringLiteral("ttyBUS"));
    auto killed = std::make_unique<SimProcess>();
    ASSERT_TRUE(startOn(*killed, link, QStringLiteral("dcpid@1")));
    const qint64 gone = killed->process().processId();
    killed->process().kill(); // SIGKILL: no clean-up
    ASSERT_TRUE(killed->process().waitForFinished(5000));
    killed.reset();
    ASSERT_TRUE(QFileInfo(link).isSymLink());
    ASSERT_EQ(lockHolder(link), gone);

    SimProcess next;
    ASSERT_TRUE(startOn(next, link, QStringLiteral("dbu200@1")));
    EXPECT_EQ(QFileInfo(link).symLinkTarget(), next.pty);
    EXPECT_EQ(lockHolder(link), next.process().processId());
    const QString row = scanRow(link);
    EXPECT_TRUE(row.contains(QStringLiteral(" dbu ")) && row.endsWith(QStringLiteral("online")))
        << row.toStdString();
    EXPECT_EQ(next.terminate(), 0);
    EXPECT_FALSE(QFileInfo::exists(link + QStringLiteral(".lock")));
}
