// Trend history and its CSV form, from hand-made samples of the DBU profile.
#include "model/monitor/TrendHistory.h"
#include "model/monitor/DeviceMonitor.h"
#include "model/monitor/TrendCsv.h"
#include "model/profile/ProfileRegistry.h"

#include <gtest/gtest.h>

using namespace opentop;

namespace {

const Profile& dbu()
{
    return *ProfileRegistry::builtIn().family(QStringLiteral("dbu"));
}

// A sample of speed, load and status at `ms` after a fixed start.
MonitorSample sample(qint64 ms, double speed, double load, bool reverse = false)
{
    MonitorSample s;
    s.slave = 1;
    s.timestamp = QDateTime::fromMSecsSinceEpoch(1'700'000'000'000 + ms);
    for (const auto& [name, value] : {std::pair(QStringLiteral("status.current_speed"), speed),
                                      std::pair(QStringLiteral("status.load"), load),
                                      std::pair(QStringLiteral("status.driver"), 2.0),
                                      std::pair(QStringLiteral("core.control_priority"), 2.0)}) {
        MonitorValue v;
        v.meta = dbu().parameter(name);
        v.value.valid = true;
        v.value.raw = value;
        v.value.number = value;
        s.values << v;
    }
    s.reverse = reverse;
    return s;
}

} // namespace

TEST(TrendHistoryTest, KeepsNumericQuantitiesWithUnitsAndSignsReverseSpeeds)
{
    TrendHistory h;
    h.append(sample(0, 1000, 20));
    h.append(sample(100, 1200, 25, true));
    // Bits and enumerations are states, not trends.
    ASSERT_EQ(h.series().size(), 2);
    const TrendHistory::Series* speed = h.find(QStringLiteral("status.current_speed"));
    ASSERT_NE(speed, nullptr);
    EXPECT_EQ(speed->unit, QStringLiteral("r/min"));
    EXPECT_EQ(speed->label, QStringLiteral("Current speed"));
    ASSERT_EQ(speed->points.size(), 2);
    EXPECT_EQ(speed->points[0].value, 1000);
    EXPECT_EQ(speed->points[1].value, -1200);
    EXPECT_EQ(h.find(QStringLiteral("status.load"))->unit, QStringLiteral("%"));
    EXPECT_EQ(h.find(QStringLiteral("status.driver")), nullptr);
}

TEST(TrendHistoryTest, DropsTheOldestBeyondItsCapacity)
{
    TrendHistory h(100);
    for (int i = 0; i < 1000; ++i)
        h.append(sample(i * 100, i, 0));
    const TrendHistory::Series* speed = h.find(QStringLiteral("status.current_speed"));
    ASSERT_NE(speed, nullptr);
    EXPECT_LE(speed->points.size(), 100);
    EXPECT_GE(speed->points.size(), 90);
    EXPECT_EQ(speed->points.last().value, 999); // the newest always stays
    EXPECT_LT(speed->points.first().ms, speed->points.last().ms);
}

TEST(TrendHistoryTest, CountsThePointsOfAllSeries)
{
    TrendHistory h(100);
    EXPECT_EQ(h.pointCount(), 0);
    for (int i = 0; i < 30; ++i)
        h.append(sample(i * 100, i, 5));
    // Speed and load are trends; the driver state and the priority are not.
    ASSERT_EQ(h.series().size(), 2);
    EXPECT_EQ(h.pointCount(), 60);
    for (int i = 30; i < 1000; ++i)
        h.append(sample(i * 100, i, 5));
    EXPECT_EQ(h.pointCount(), h.series()[0].points.size() + h.series()[1].points.size());
    EXPECT_LE(h.pointCount(), 200);
}

TEST(TrendHistoryTest, ASmallerCapacityDropsTheOldestAtOnce)
{
    TrendHistory h(1000);
    for (int i = 0; i < 500; ++i)
        h.append(sample(i * 100, i, 0));
    h.setCapacity(100);
    EXPECT_EQ(h.capacity(), 100);
    const TrendHistory::Series* speed = h.find(QStringLiteral("status.current_speed"));
    ASSERT_NE(speed, nullptr);
    ASSERT_EQ(speed->points.size(), 100);
    EXPECT_EQ(speed->points.first().value, 400);
    EXPECT_EQ(speed->points.last().value, 499);
}

TEST(TrendHistoryTest, ValueAtIsTheNewestPointAtOrBeforeATime)
{
    TrendHistory h;
    h.append(sample(0, 100, 0));
    h.append(sample(100, 200, 0));
    h.append(sample(50, 999, 0)); // out of order: ignored
    const TrendHistory::Series& s = *h.find(QStringLiteral("status.current_speed"));
    const qint64 t0 = s.points.first().ms;
    double v = 0;
    EXPECT_FALSE(TrendHistory::valueAt(s, t0 - 1, &v));
    ASSERT_TRUE(TrendHistory::valueAt(s, t0 + 99, &v));
    EXPECT_EQ(v, 100);
    ASSERT_TRUE(TrendHistory::valueAt(s, t0 + 100, &v));
    EXPECT_EQ(v, 200);
    EXPECT_EQ(TrendHistory::lowerBound(s, t0 + 1), 1);
    EXPECT_EQ(TrendHistory::lowerBound(s, t0 + 101), 2);
}

TEST(TrendCsvTest, MergesDrivesByTimeWithUnitsInTheHeader)
{
    TrendHistory a;
    TrendHistory b;
    a.append(sample(0, 100, 10));
    b.append(sample(50, 300, 30));
    a.append(sample(100, 200, 20));
    const QVector<TrendCsv::Column> columns{
        {QStringLiteral("drive 1"), a.find(QStringLiteral("status.current_speed"))},
        {QStringLiteral("drive 2"), b.find(QStringLiteral("status.current_speed"))},
        {QStringLiteral("drive 1"), a.find(QStringLiteral("status.load"))}};
    const QStringList lines =
        QString::fromUtf8(TrendCsv::toCsv(columns)).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    ASSERT_EQ(lines.size(), 4);
    EXPECT_EQ(lines[0], QStringLiteral("time,seconds,drive 1 Current speed [r/min],drive 2 Current "
                                       "speed [r/min],drive 1 Load rate [%]"));
    EXPECT_TRUE(lines[1].endsWith(QStringLiteral(",0.000,100,,10"))) << qPrintable(lines[1]);
    EXPECT_TRUE(lines[2].endsWith(QStringLiteral(",0.050,,300,"))) << qPrintable(lines[2]);
    EXPECT_TRUE(lines[3].endsWith(QStringLiteral(",0.100,200,,20"))) << qPrintable(lines[3]);
    // A time range keeps only the rows inside it.
    const qint64 t0 = a.series().first().points.first().ms;
    const QStringList ranged = QString::fromUtf8(TrendCsv::toCsv(columns, t0 + 40, t0 + 60))
                                   .split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    ASSERT_EQ(ranged.size(), 2);
    EXPECT_TRUE(ranged[1].endsWith(QStringLiteral(",0.000,,300,"))) << qPrintable(ranged[1]);
}
