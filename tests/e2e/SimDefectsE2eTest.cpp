// Simulated defects end to end: the opentop-sim executable started with --defect on a pty, and
// opentop-cli seeing what an end-of-line test must catch: another firmware (scan), a motor
// saturating below its target with a high load (monitor), an alarm while running (alarms), a
// setting that does not stick (set fails its verification). The console changes them live; bad
// defects are usage errors of both programs.
#include "tests/e2e/CliProcess.h"
#include "tests/e2e/SimProcess.h"

#include <QProcess>
#include <QThread>

using namespace opentop::test;

namespace {

CliResult cli(const QString& port, const QStringList& args)
{
    return runCliOn(port, args, 20000);
}

// The output line of machine number `id` (a table row starting with the number).
QString rowOf(const QString& text, int id)
{
    for (const QString& line : text.split(QLatin1Char('\n'))) {
        if (line.trimmed().startsWith(QString::number(id) + QLatin1Char(' ')))
            return line;
    }
    return QString();
}

} // namespace

TEST(SimDefectsE2e, CliSeesEveryDefectOverThePty)
{
    SimProcess sim;
    QString error;
    ASSERT_TRUE(sim.start({QStringLiteral("--devices"), QStringLiteral("dbu200@1-4,dcpid@7"),
                           QStringLiteral("--defect"), QStringLiteral("1:firmware=1.4"),
                           QStringLiteral("--defect"), QStringLiteral("2:max_speed=300"),
                           QStringLiteral("--defect=3:alarm=overload@1s"),
                           QStringLiteral("--defect"), QStringLiteral("4:nostick=spno2.speed"),
                           QStringLiteral("--defect"), QStringLiteral("7:firmware=2.1")},
                          &error))
        << error.toStdString();

    // Another firmware, on both families.
    CliResult r =
        cli(sim.pty, {QStringLiteral("scan"), QStringLiteral("--to"), QStringLiteral("8")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(rowOf(r.out, 1).contains(QStringLiteral("V1.4"))) << r.out.toStdString();
    EXPECT_TRUE(rowOf(r.out, 2).contains(QStringLiteral("V1.5"))) << r.out.toStdString();
    EXPECT_TRUE(rowOf(r.out, 7).contains(QStringLiteral("V2.1"))) << r.out.toStdString();

    // A setting that does not stick: acknowledged, but the read-back finds the old value.
    r = cli(sim.pty,
            {QStringLiteral("set"), QStringLiteral("4"), QStringLiteral("spno2.speed=1500")});
    EXPECT_EQ(r.code, 4) << (r.out + r.err).toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("the device holds 1000 r/min")))
        << r.out.toStdString();
    r = cli(sim.pty,
            {QStringLiteral("set"), QStringLiteral("1"), QStringLiteral("spno2.speed=1500")});
    EXPECT_EQ(r.code, 0) << (r.out + r.err).toStdString();

    // A motor that cannot reach its speed (SPno1, 500 r/min), at its torque limit.
    for (int id : {2, 3})
        sim.command(QStringLiteral("set %1 0x100D 2").arg(id)); // communication priority
    r = cli(sim.pty, {QStringLiteral("run"), QStringLiteral("2"), QStringLiteral("start"),
                      QStringLiteral("--yes")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    QThread::msleep(500);
    r = cli(sim.pty, {QStringLiteral("monitor"), QStringLiteral("2"), QStringLiteral("--count"),
                      QStringLiteral("1")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    const QString row = r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts).value(1); // a header
    EXPECT_TRUE(row.contains(QStringLiteral("    2  "))) << r.out.toStdString();
    EXPECT_TRUE(row.contains(QStringLiteral(" 300 r/min"))) << r.out.toStdString();
    EXPECT_TRUE(row.contains(QStringLiteral(" 500 r/min"))) << r.out.toStdString(); // target
    EXPECT_TRUE(row.contains(QStringLiteral("115 %"))) << r.out.toStdString();

    // An alarm while running: the drive stops and records it.
    r = cli(sim.pty, {QStringLiteral("run"), QStringLiteral("3"), QStringLiteral("start"),
                      QStringLiteral("--yes")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    QThread::msleep(1500);
    r = cli(sim.pty, {QStringLiteral("alarms"), QStringLiteral("3")});
    EXPECT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("Alarm active: AL007 Overload")))
        << r.out.toStdString();
    EXPECT_EQ(sim.get(3, 0x0109, 4), 0); // current speed

    // Live changes on the console.
    EXPECT_EQ(sim.command(QStringLiteral("defect 2 clear")),
              QStringLiteral("slave 2 defects: none"));
    QThread::msleep(500);
    EXPECT_EQ(sim.get(2, 0x0109, 4), 500);
    EXPECT_TRUE(sim.command(QStringLiteral("defect 2 firmware=3.7"))
                    .contains(QStringLiteral("firmware=3.7")));
    EXPECT_EQ(sim.get(2, 0x000B, 4), 0x0307);
    EXPECT_TRUE(sim.command(QStringLiteral("defect 2 alarm=0x02@1s"))
                    .startsWith(QStringLiteral("error: alarm=0x02: not an alarm")));
    EXPECT_EQ(sim.command(QStringLiteral("defects")), QStringLiteral("1 dbu200: firmware=1.4"));
    EXPECT_EQ(sim.readLine(3000).value_or(QString()), QStringLiteral("2 dbu200: firmware=3.7"));
    EXPECT_EQ(sim.readLine(3000).value_or(QString()),
              QStringLiteral("3 dbu200: alarm=overload@1000ms"));
    EXPECT_EQ(sim.readLine(3000).value_or(QString()),
              QStringLiteral("4 dbu200: nostick=spno2.speed"));
    EXPECT_EQ(sim.readLine(3000).value_or(QString()), QStringLiteral("7 dcpid: firmware=2.1"));
    EXPECT_EQ(sim.terminate(), 0);
}

TEST(SimDefectsE2e, BadDefectsAreUsageErrors)
{
    const struct
    {
        QStringList arguments;
        const char* message;
    } cases[] = {
        {{QStringLiteral("--defect"), QStringLiteral("1:speed=3")}, "unknown defect \"speed=3\""},
        {{QStringLiteral("--defect"), QStringLiteral("9:stall")}, "no drive with machine number 9"},
        {{QStringLiteral("--defect"), QStringLiteral("1:alarm=0x02@1s")}, "0x07 overload"},
        {{QStringLiteral("--defect"), QStringLiteral("7:alarm=0x07@1s")}, "alarm=stall@TIME"},
        {{QStringLiteral("--defect"), QStringLiteral("stall")}, "ID:DEFECT"},
    };
    for (const auto& c : cases) {
        QProcess sim;
        sim.start(SimProcess::program(),
                  QStringList{QStringLiteral("--devices"), QStringLiteral("dbu200@1,dcpid@7")} +
                      c.arguments);
        ASSERT_TRUE(sim.waitForFinished(10000));
        EXPECT_EQ(sim.exitCode(), 2) << c.message;
        const QString err = QString::fromLocal8Bit(sim.readAllStandardError());
        EXPECT_TRUE(err.contains(QString::fromUtf8(c.message))) << err.toStdString();
    }
    // In-process: a drive's defects in braces of --sim, checked before anything is sent.
    QProcess cliProcess;
    cliProcess.start(
        cliProgram(),
        {QStringLiteral("--sim"), QStringLiteral("dbu200@1{firmwar=1.4}"), QStringLiteral("scan")});
    ASSERT_TRUE(cliProcess.waitForStarted(5000));
    CliResult r = finishCli(cliProcess);
    EXPECT_EQ(r.code, 2) << (r.out + r.err).toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("unknown defect \"firmwar=1.4\"")))
        << r.err.toStdString();
    QProcess good;
    good.start(cliProgram(), {QStringLiteral("--sim"), QStringLiteral("dbu200@1{firmware=1.4}"),
                              QStringLiteral("scan"), QStringLiteral("--to"), QStringLiteral("2")});
    ASSERT_TRUE(good.waitForStarted(5000));
    r = finishCli(good);
    EXPECT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(rowOf(r.out, 1).contains(QStringLiteral("V1.4"))) << r.out.toStdString();
}
