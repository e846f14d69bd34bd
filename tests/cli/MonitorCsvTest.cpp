// `monitor --csv FILE` reports a CSV it cannot write (a full device) and stops, instead of going
// on as if the samples were recorded; a FIFO is written through.
#include "cli/ExitCode.h"
#include "tests/cli/CliTestSupport.h"
#include "tests/support/FifoReader.h"

#include <QFileInfo>
#include <QTemporaryDir>
#include <gtest/gtest.h>

TEST(MonitorCsv, AFullDeviceIsAnErrorAndStopsTheMonitor)
{
    if (!QFileInfo::exists(QStringLiteral("/dev/full")))
        GTEST_SKIP() << "no /dev/full here";
    const CliRun r =
        runCli({QStringLiteral("--sim"), QStringLiteral("dbu200@1"), QStringLiteral("monitor"),
                QStringLiteral("1"), QStringLiteral("--count"), QStringLiteral("20"),
                QStringLiteral("--interval"), QStringLiteral("50"), QStringLiteral("--csv"),
                QStringLiteral("/dev/full")});
    EXPECT_EQ(r.code, opentop::ExitUsage) << qPrintable(r.out + r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("error: cannot write /dev/full: ")))
        << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("monitoring stopped"))) << qPrintable(r.err);
    EXPECT_LT(r.out.count(QLatin1Char('\n')), 20) << "stopped at the first failed row";
}

TEST(MonitorCsv, AFifoIsWrittenThrough)
{
    QTemporaryDir dir;
    CliRun r;
    bool stillFifo = false;
    const QByteArray got = opentop::test::saveThroughFifo(
        dir.path(),
        [&](const QString& path) {
            r = runCli({QStringLiteral("--sim"), QStringLiteral("dbu200@1"),
                        QStringLiteral("monitor"), QStringLiteral("1"), QStringLiteral("--count"),
                        QStringLiteral("2"), QStringLiteral("--interval"), QStringLiteral("50"),
                        QStringLiteral("--csv"), path});
        },
        &stillFifo);
    EXPECT_EQ(r.code, opentop::ExitOk) << qPrintable(r.err);
    EXPECT_TRUE(stillFifo);
    EXPECT_EQ(got.count('\n'), 3) << got.constData(); // header and two samples
}
