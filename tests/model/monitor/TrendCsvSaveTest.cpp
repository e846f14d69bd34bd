// Saving a trend CSV goes through OutputFile: a FIFO or device is written through (never
// replaced by a regular file), a full device or a missing folder is an error, not success.
#include "model/monitor/DeviceMonitor.h"
#include "model/monitor/TrendCsv.h"
#include "model/monitor/TrendHistory.h"
#include "model/profile/ProfileRegistry.h"
#include "tests/support/FifoReader.h"

#include <QFileInfo>
#include <QTemporaryDir>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

struct OneSeries
{
    TrendHistory history;
    QVector<TrendCsv::Column> columns;
    OneSeries()
    {
        const Profile& dbu = *ProfileRegistry::builtIn().family(QStringLiteral("dbu"));
        MonitorSample s;
        s.slave = 1;
        s.timestamp = QDateTime::fromMSecsSinceEpoch(1'700'000'000'000);
        MonitorValue v;
        v.meta = dbu.parameter(QStringLiteral("status.current_speed"));
        v.value.valid = true;
        v.value.raw = v.value.number = 1200;
        s.values << v;
        history.append(s);
        columns << TrendCsv::Column{QStringLiteral("drive 1"),
                                    history.find(QStringLiteral("status.current_speed"))};
    }
};

} // namespace

TEST(TrendCsvSaveTest, AFifoIsWrittenThroughAndStaysAFifo)
{
    OneSeries one;
    QTemporaryDir dir;
    bool ok = false;
    QString error;
    bool stillFifo = false;
    const QByteArray got = test::saveThroughFifo(
        dir.path(),
        [&](const QString& path) { ok = TrendCsv::write(path, one.columns, 0, -1, &error); },
        &stillFifo);
    EXPECT_TRUE(ok) << qPrintable(error);
    EXPECT_TRUE(stillFifo) << "the FIFO was replaced by a regular file";
    EXPECT_EQ(got, TrendCsv::toCsv(one.columns));
}

TEST(TrendCsvSaveTest, AFullDeviceOrAMissingFolderIsAnError)
{
    OneSeries one;
    QString error;
    if (QFileInfo::exists(QStringLiteral("/dev/full"))) {
        EXPECT_FALSE(TrendCsv::write(QStringLiteral("/dev/full"), one.columns, 0, -1, &error));
        EXPECT_TRUE(error.startsWith(QStringLiteral("cannot write /dev/full: ")))
            << qPrintable(error);
        EXPECT_FALSE(QFileInfo(QStringLiteral("/dev/full")).isFile()) << "/dev/full replaced";
    }
    QTemporaryDir dir;
    const QString missing = dir.filePath(QStringLiteral("no-such-folder/trend.csv"));
    EXPECT_FALSE(TrendCsv::write(missing, one.columns, 0, -1, &error));
    EXPECT_TRUE(error.contains(missing)) << qPrintable(error);
    EXPECT_FALSE(TrendCsv::write(dir.path(), one.columns, 0, -1, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("it is a directory"))) << qPrintable(error);
}
