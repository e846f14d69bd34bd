// The port pulled out under opentop-cli (the simulator's console "unplug" closes the pty) in
// the middle of a backup: one clear error naming the port, exit 1, nothing written; after
// "replug" the backup completes. Real processes, exit codes and messages.
#include "tests/e2e/CliProcess.h"
#include "tests/e2e/SimProcess.h"

#include <QElapsedTimer>
#include <QFileInfo>
#include <QTemporaryDir>

using namespace opentop::test;

TEST(CliVanishE2e, BackupLosingItsPortSaysSoOnceAndWritesNothing)
{
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString link = dir.filePath(QStringLiteral("ttyVANISH"));
    const QString file = dir.filePath(QStringLiteral("bus.json"));
    SimProcess sim;
    QString error;
    ASSERT_TRUE(sim.start({QStringLiteral("--devices"),
                           QStringLiteral("dbu200@1,dbu200@2,dbu200@3,dbu200@4"),
                           QStringLiteral("--wire-timing"), QStringLiteral("--pty"), link},
                          &error))
        << error.toStdString();
    const QStringList backup{QStringLiteral("--port"),    link,
                             QStringLiteral("--variant"), QStringLiteral("dbu200"),
                             QStringLiteral("backup"),    QStringLiteral("1-4"),
                             QStringLiteral("-o"),        file};
    QProcess cli;
    cli.start(cliProgram(), backup + QStringList{QStringLiteral("--trace")});
    ASSERT_TRUE(cli.waitForStarted(5000));
    QString trace;
    QElapsedTimer timer;
    timer.start();
    while (!trace.contains(QStringLiteral("TX #2 02 03")) && timer.elapsed() < 20000) {
        cli.waitForReadyRead(20);
        trace += QString::fromUtf8(cli.readAllStandardError());
    }
    ASSERT_TRUE(trace.contains(QStringLiteral("TX #2 02 03"))) << trace.toStdString();
    EXPECT_EQ(sim.command(QStringLiteral("unplug")), QStringLiteral("unplugged"));
    CliResult r = finishCli(cli);
    r.err = trace + r.err;
    EXPECT_EQ(r.code, 1) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(
        QStringLiteral("error: the port %1 was lost while reading drive 2").arg(link)))
        << r.err.toStdString();
    int errors = 0; // lines for the user, not the trace's
    for (const QString& line : r.err.split(QLatin1Char('\n')))
        errors += line.startsWith(QLatin1String("error:"));
    EXPECT_EQ(errors, 1) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("nothing written to %1").arg(file)));
    EXPECT_FALSE(QFileInfo::exists(file));

    EXPECT_TRUE(sim.command(QStringLiteral("replug")).startsWith(QStringLiteral("pty: ")));
    r = runCliOn(link, backup.mid(2));
    EXPECT_EQ(r.code, 0) << (r.out + r.err).toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("wrote %1: 4 drive").arg(file)))
        << r.out.toStdString();
}
