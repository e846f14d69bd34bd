// Output piped into `head` or a pager quit early (issue 28, item 3): the closed pipe never stops
// a restore halfway. Every drive is restored, the exit status is the work's, and stderr says that
// standard output was lost. opentop-cli over a pty against opentop-sim.
#include "tests/e2e/CliProcess.h"
#include "tests/e2e/SimProcess.h"

#include <QTemporaryDir>

using namespace opentop::test;

TEST(CliClosedPipeE2e, ARestoreWhoseOutputPipeClosesRestoresEveryDrive)
{
    SimProcess sim;
    QString error;
    ASSERT_TRUE(
        sim.start({QStringLiteral("--devices"), QStringLiteral("dbu200@1,dbu200@2,dbu200@3"),
                   QStringLiteral("--wire-timing")},
                  &error))
        << qPrintable(error);
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString file = dir.filePath(QStringLiteral("line.json"));
    const QStringList common{QStringLiteral("--port"), sim.pty, QStringLiteral("--variant"),
                             QStringLiteral("dbu200"), QStringLiteral("--bus-drives=1-3")};
    CliResult r =
        runCliOn(sim.pty, QStringList{QStringLiteral("--variant"), QStringLiteral("dbu200"),
                                      QStringLiteral("--bus-drives=1-3"), QStringLiteral("backup"),
                                      QStringLiteral("1-3"), QStringLiteral("-o"), file});
    ASSERT_EQ(r.code, 0) << qPrintable(r.err);
    const int kept = sim.get(3, 0xCA03);
    for (int id : {1, 2, 3})
        sim.command(QStringLiteral("set %1 0xCA03 %2").arg(id).arg(kept + 100 * id));

    // opentop-cli … restore … | head -c 0: the reader is gone before the first line.
    QProcess restore;
    QProcess head;
    restore.setStandardOutputProcess(&head);
    head.start(QStringLiteral("head"), {QStringLiteral("-c"), QStringLiteral("0")});
    restore.start(cliProgram(),
                  common + QStringList{QStringLiteral("restore"), file, QStringLiteral("--yes")});
    ASSERT_TRUE(restore.waitForStarted(5000));
    ASSERT_TRUE(head.waitForFinished(5000));
    ASSERT_TRUE(restore.waitForFinished(60000));
    EXPECT_EQ(restore.exitStatus(), QProcess::NormalExit) << "killed by SIGPIPE";
    EXPECT_EQ(restore.exitCode(), 0);
    const QString err = QString::fromUtf8(restore.readAllStandardError());
    EXPECT_TRUE(err.contains(QStringLiteral("standard output could not be written")))
        << qPrintable(err);
    for (int id : {1, 2, 3})
        EXPECT_EQ(sim.get(id, 0xCA03), kept) << "drive " << id << " was not restored";
    sim.terminate();
}
