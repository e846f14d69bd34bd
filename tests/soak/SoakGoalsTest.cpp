#include "tests/soak/SoakGoals.h"

#include <gtest/gtest.h>

using opentop::soak::SoakGoals;
using opentop::soak::SoakPoint;

namespace {

// A two-minute run with a line every 10 s: flat figures, 80 samples/s.
QVector<SoakPoint> steadyRun()
{
    QVector<SoakPoint> points;
    for (int i = 0; i <= 12; ++i) {
        SoakPoint p;
        p.elapsedS = i * 10;
        p.rssKb = 100000 + (i % 2) * 300; // a little noise
        p.fds = 20;
        p.threads = 6;
        p.samplesPerS = i == 0 ? 0 : 80.0 + (i % 3);
        points << p;
    }
    return points;
}

bool mentions(const QStringList& missed, const QString& what)
{
    for (const QString& m : missed) {
        if (m.contains(what))
            return true;
    }
    return false;
}

} // namespace

TEST(SoakGoalsTest, SteadyFiguresMeetEveryGoal)
{
    const SoakGoals::Summary s = SoakGoals::check(QStringLiteral("gui"), steadyRun(), 120);
    EXPECT_TRUE(s.missed.isEmpty()) << s.missed.join(QLatin1Char('\n')).toStdString();
    EXPECT_EQ(s.fdsBase, 20);
    EXPECT_EQ(s.threadsEnd, 6);
    EXPECT_DOUBLE_EQ(s.rateMin, 80.0);
    EXPECT_DOUBLE_EQ(s.rateMax, 82.0);
}

TEST(SoakGoalsTest, WarmupIsFiveMinutesOrAFifthOfAShortRun)
{
    EXPECT_DOUBLE_EQ(SoakGoals::warmupS(3600), 300);
    EXPECT_DOUBLE_EQ(SoakGoals::warmupS(120), 24);
}

TEST(SoakGoalsTest, AGivenWarmupMovesTheBaseline)
{
    QVector<SoakPoint> points = steadyRun();
    for (int i = 0; i < points.size(); ++i)
        points[i].rssKb = i <= 6 ? 100000 + i * 2000 : 112000; // flat from 60 s on
    EXPECT_EQ(SoakGoals::check(QStringLiteral("gui"), points, 120).missed.size(), 1);
    const SoakGoals::Summary s = SoakGoals::check(QStringLiteral("gui"), points, 120, 60);
    EXPECT_TRUE(s.missed.isEmpty()) << s.missed.join(QLatin1Char('\n')).toStdString();
    EXPECT_EQ(s.rssBaseKb, 112000);
}

TEST(SoakGoalsTest, GrowingMemoryMissesTheRssGoal)
{
    QVector<SoakPoint> points = steadyRun();
    for (int i = 0; i < points.size(); ++i)
        points[i].rssKb = 100000 + i * 1000; // 1 % a line: 9 % from 30 s to the end
    const SoakGoals::Summary s = SoakGoals::check(QStringLiteral("model"), points, 120);
    ASSERT_EQ(s.missed.size(), 1);
    EXPECT_TRUE(s.missed.first().startsWith(
        QStringLiteral("model: RSS grew 8.7 % beyond the trend histories")))
        << s.missed.first().toStdString();
    EXPECT_TRUE(mentions(SoakGoals::describe(s), QStringLiteral("goal missed: model: RSS")));
}

TEST(SoakGoalsTest, TrendHistoriesFillingUpAreNotALeakButTheRestIs)
{
    QVector<SoakPoint> points = steadyRun();
    for (int i = 0; i < points.size(); ++i) {
        points[i].rssKb = 100000 + i * 1000;
        points[i].trendKb = 2000 + i * 1000; // all of the growth
    }
    const SoakGoals::Summary s = SoakGoals::check(QStringLiteral("gui"), points, 120);
    EXPECT_TRUE(s.missed.isEmpty()) << s.missed.join(QLatin1Char('\n')).toStdString();
    EXPECT_NEAR(s.rssGrowth, 9000.0 / 103000.0, 1e-9); // shown as it is
    EXPECT_NEAR(s.otherGrowth, 0.0, 1e-9);
    for (int i = 0; i < points.size(); ++i)
        points[i].trendKb = 2000 + i * 400; // less than half of it
    EXPECT_EQ(SoakGoals::check(QStringLiteral("gui"), points, 120).missed.size(), 1);
}

TEST(SoakGoalsTest, GrowthDuringTheWarmupDoesNotCount)
{
    QVector<SoakPoint> points = steadyRun();
    points[0].rssKb = 50000; // caches filling up in the first seconds
    points[1].rssKb = 80000;
    points[2].rssKb = 95000;
    EXPECT_TRUE(SoakGoals::check(QStringLiteral("gui"), points, 120).missed.isEmpty());
}

TEST(SoakGoalsTest, GrowthJustUnderFivePercentPassesAndAtFivePercentFails)
{
    QVector<SoakPoint> points = steadyRun();
    for (SoakPoint& p : points)
        p.rssKb = 100000;
    points.last().rssKb = 104900;
    EXPECT_TRUE(SoakGoals::check(QStringLiteral("gui"), points, 120).missed.isEmpty());
    points.last().rssKb = 105000;
    EXPECT_EQ(SoakGoals::check(QStringLiteral("gui"), points, 120).missed.size(), 1);
}

TEST(SoakGoalsTest, MoreFileDescriptorsOrThreadsAtTheEndMissTheirGoals)
{
    QVector<SoakPoint> points = steadyRun();
    points.last().fds = 21;
    points.last().threads = 8;
    const SoakGoals::Summary s = SoakGoals::check(QStringLiteral("gui"), points, 120);
    EXPECT_TRUE(mentions(s.missed, QStringLiteral("open file descriptors grew from 20 to 21")));
    EXPECT_TRUE(mentions(s.missed, QStringLiteral("threads grew from 6 to 8")));
    EXPECT_EQ(s.missed.size(), 2);
}

TEST(SoakGoalsTest, AThreadThatComesAndGoesIsNoGrowth)
{
    QVector<SoakPoint> points = steadyRun();
    points[1].threads = 7; // a pool thread during the warm-up
    points[8].threads = 7; // and later, gone again at the end
    EXPECT_TRUE(SoakGoals::check(QStringLiteral("gui"), points, 120).missed.isEmpty());
}

TEST(SoakGoalsTest, AFallingSampleRateMissesTheSteadyRateGoal)
{
    QVector<SoakPoint> points = steadyRun();
    points.last().samplesPerS = 70; // median 81: 13.6 % below
    const SoakGoals::Summary s = SoakGoals::check(QStringLiteral("gui"), points, 120);
    ASSERT_EQ(s.missed.size(), 1);
    EXPECT_TRUE(s.missed.first().contains(QStringLiteral("sample rate not steady")));
    points.last().samplesPerS = 74; // 8.6 % below: steady enough
    EXPECT_TRUE(SoakGoals::check(QStringLiteral("gui"), points, 120).missed.isEmpty());
}

TEST(SoakGoalsTest, NoSamplesAtAllMissesTheRateGoal)
{
    QVector<SoakPoint> points = steadyRun();
    for (SoakPoint& p : points)
        p.samplesPerS = 0;
    EXPECT_TRUE(mentions(SoakGoals::check(QStringLiteral("gui"), points, 120).missed,
                         QStringLiteral("no samples")));
}

TEST(SoakGoalsTest, ARunTooShortToJudgeIsAMissedGoal)
{
    const QVector<SoakPoint> points = steadyRun().mid(0, 3); // 0, 10 and 20 s of 120
    const SoakGoals::Summary s = SoakGoals::check(QStringLiteral("gui"), points, 120);
    ASSERT_EQ(s.missed.size(), 1);
    EXPECT_TRUE(s.missed.first().contains(QStringLiteral("too few figure lines")));
}

TEST(SoakGoalsTest, LostSamplesAndStaleDrivesAreReported)
{
    QVector<SoakPoint> points = steadyRun();
    points[5].lost = 2;
    points[9].lost = 1;
    points[9].stale = 3;
    const SoakGoals::Summary s = SoakGoals::check(QStringLiteral("gui"), points, 120);
    EXPECT_EQ(s.lost, 3);
    EXPECT_EQ(s.staleMax, 3);
    EXPECT_TRUE(mentions(SoakGoals::describe(s), QStringLiteral("3 lost in all")));
}
