// What a trend chart draws: thinning out long series and round axis ranges.
#include "ui/trends/TrendPoints.h"

#include <algorithm>
#include <gtest/gtest.h>

using namespace opentop;

TEST(TrendPointsTest, ShortWindowsKeepEveryPointPlusOneEitherSide)
{
    TrendHistory::Series s;
    for (int i = 0; i < 100; ++i)
        s.points << TrendHistory::Point{1000 + i * 100, double(i)};
    const QList<QPointF> p = TrendPoints::visible(s, 3000, 5000, 200);
    ASSERT_EQ(p.size(), 21 + 2);
    EXPECT_EQ(p.first().x(), 2900.0);
    EXPECT_EQ(p.last().x(), 5100.0);
    EXPECT_TRUE(TrendPoints::visible(TrendHistory::Series(), 0, 10, 10).isEmpty());
}

TEST(TrendPointsTest, LongWindowsKeepEachBucketsExtremesInTimeOrder)
{
    // An hour at 10 Hz with one spike: at most two points per bucket, the spike among them.
    TrendHistory::Series s;
    for (int i = 0; i < 36000; ++i)
        s.points << TrendHistory::Point{qint64(i) * 100, i == 12345 ? 5000.0 : double(i % 50)};
    const QList<QPointF> p = TrendPoints::visible(s, 0, 3600000, 800);
    EXPECT_LE(p.size(), 2 * 800 + 2);
    EXPECT_GT(p.size(), 800);
    bool spike = false;
    for (int i = 0; i < p.size(); ++i) {
        spike = spike || p[i].y() == 5000.0;
        if (i > 0) {
            EXPECT_LT(p[i - 1].x(), p[i].x());
        }
    }
    EXPECT_TRUE(spike);
}

TEST(TrendPointsTest, RangesGetAirAndRoundTicks)
{
    double lo = 0;
    double hi = 2100;
    TrendPoints::pad(&lo, &hi);
    EXPECT_EQ(lo, 0.0); // a ramp from standstill does not reach below zero
    EXPECT_DOUBLE_EQ(hi, 2205.0);
    EXPECT_EQ(TrendPoints::niceTicks(&lo, &hi, 6), 6);
    EXPECT_EQ(lo, 0.0);
    EXPECT_EQ(hi, 2500.0);

    lo = -1500;
    hi = -1500;
    TrendPoints::pad(&lo, &hi);
    EXPECT_LT(lo, -1500.0);
    EXPECT_GT(hi, -1500.0);
    lo = 1;
    hi = 0; // no values
    TrendPoints::pad(&lo, &hi);
    EXPECT_EQ(lo, 0.0);
    EXPECT_EQ(hi, 1.0);
    EXPECT_GE(TrendPoints::niceTicks(&lo, &hi, 6), 5);
}

TEST(TrendPointsTest, AGapSplitsTheLineIntoSegmentsThatNeverJoinAcrossIt)
{
    // 5 Hz for 2 s, nothing for 7 s (polling stopped), 5 Hz for 2 s.
    TrendHistory::Series s;
    for (int i = 0; i < 10; ++i)
        s.points << TrendHistory::Point{1000 + i * 200, 0.0};
    for (int i = 0; i < 10; ++i)
        s.points << TrendHistory::Point{10000 + i * 200, 1350.0};
    const QVector<QList<QPointF>> parts = TrendPoints::segments(s, 0, 20000, 800, 1500);
    ASSERT_EQ(parts.size(), 2);
    EXPECT_EQ(parts[0].size(), 10);
    EXPECT_EQ(parts[0].last().x(), 2800.0);
    EXPECT_EQ(parts[1].first().x(), 10000.0);
    EXPECT_EQ(parts[1].first().y(), 1350.0);
    // Without a gap longer than allowed it is one line, as visible() draws it.
    const QVector<QList<QPointF>> one = TrendPoints::segments(s, 0, 20000, 800, 10000);
    ASSERT_EQ(one.size(), 1);
    EXPECT_EQ(one.first(), TrendPoints::visible(s, 0, 20000, 800));
    EXPECT_TRUE(TrendPoints::segments(TrendHistory::Series(), 0, 10, 10, 100).isEmpty());
}

TEST(TrendPointsTest, ARunOfEqualValuesKeepsItsEndsAPointPerGapAndTheWindowsEdges)
{
    // 10 Hz: standstill for 10 s, a ramp over 1 s, then the speed held for 10 s.
    QList<QPointF> p;
    for (int i = 0; i < 100; ++i)
        p << QPointF(i * 100, 0);
    for (int i = 0; i < 10; ++i)
        p << QPointF(10000 + i * 100, 150.0 * (i + 1));
    for (int i = 0; i < 100; ++i)
        p << QPointF(11000 + i * 100, 1500);
    QList<QPointF> drawn = p;
    TrendPoints::dropRepeats(&drawn, 500, 20000, 1500);
    EXPECT_LT(drawn.size(), 50);
    // Every point of the ramp and the ends of both runs stay; so does the first point in the
    // window (at 500 ms) and the last (at 20 s).
    for (const QPointF& kept : {QPointF(0, 0), QPointF(500, 0), QPointF(9900, 0),
                                QPointF(10500, 900), QPointF(20000, 1500), QPointF(20900, 1500)})
        EXPECT_TRUE(drawn.contains(kept)) << kept.x();
    for (int i = 1; i < drawn.size(); ++i)
        EXPECT_LE(drawn[i].x() - drawn[i - 1].x(), 1500.0); // a gap still shows as one
    // Nothing dropped changes the line: each dropped point lies on it.
    for (const QPointF& q : p) {
        if (drawn.contains(q))
            continue;
        const auto next = std::upper_bound(drawn.cbegin(), drawn.cend(), q.x(),
                                           [](double x, const QPointF& d) { return x < d.x(); });
        ASSERT_NE(next, drawn.cbegin());
        ASSERT_NE(next, drawn.cend());
        EXPECT_EQ(std::prev(next)->y(), q.y());
        EXPECT_EQ(next->y(), q.y());
    }
}
