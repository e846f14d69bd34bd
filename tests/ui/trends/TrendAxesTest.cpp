// Value axis titles of a trend chart: full when they fit, shortened so the unit stays.
#include "ui/trends/TrendAxes.h"

#include <QChart>
#include <QFontMetricsF>
#include <QValueAxis>
#include <gtest/gtest.h>

using namespace opentop;

TEST(TrendAxesTest, TitlesNameQuantitiesAndUnitAndShortenKeepingTheUnit)
{
    QChart chart;
    TrendAxes axes(&chart);
    axes.setQuantities({{QStringLiteral("Current speed"), QStringLiteral("r/min")},
                        {QStringLiteral("Target speed"), QStringLiteral("r/min")},
                        {QStringLiteral("Load rate"), QStringLiteral("%")}});
    EXPECT_EQ(axes.axis(0)->titleText(), QStringLiteral("Current speed, Target speed [r/min]"));
    EXPECT_EQ(axes.axis(1)->titleText(), QStringLiteral("Load rate [%]"));
    EXPECT_TRUE(axes.axis(1)->isVisible());
    // Just tall enough for the shared word and the unit, not for the full title.
    const QFontMetricsF metrics(axes.axis(0)->titleFont());
    axes.fitTitles(metrics.horizontalAdvance(QStringLiteral("Speed [r/min]")) + 1);
    EXPECT_EQ(axes.axis(0)->titleText(), QStringLiteral("Speed [r/min]"));
    // Too short for that too (a laptop's window with a dock open): the unit alone, never "S…".
    const double shorter = metrics.horizontalAdvance(QStringLiteral("Speed [r/min]")) - 1;
    axes.fitTitles(shorter);
    EXPECT_EQ(axes.axis(0)->titleText(), QStringLiteral("[r/min]"));
    const QFontMetricsF right(axes.axis(1)->titleFont());
    EXPECT_EQ(axes.axis(1)->titleText(),
              right.horizontalAdvance(QStringLiteral("Load rate [%]")) < shorter
                  ? QStringLiteral("Load rate [%]")
                  : QStringLiteral("[%]"));
    // Shorter still: the units without brackets, the right side's joined by a slash.
    axes.fitTitles(1);
    EXPECT_EQ(axes.axis(0)->titleText(), QStringLiteral("r/min"));
    EXPECT_EQ(TrendAxes::sharedWord({QStringLiteral("Motor current"), QStringLiteral("PWM duty")}),
              QString());
}

// A trend panel restored from the last session's layout before any quantity is chosen: the
// chart lays itself out (plotAreaChanged) with no titles at all. It crashed the window, on
// Linux and on Windows, about 3 s after start (issue 29, found by the Windows check).
TEST(TrendAxesTest, AChartWithoutQuantitiesFitsNoTitlesAndKeepsRunning)
{
    QChart chart;
    TrendAxes axes(&chart);
    axes.fitTitles(200);
    axes.fitTitles(0);
    EXPECT_EQ(axes.axis(0)->titleText(), QString());
    EXPECT_EQ(axes.axis(1)->titleText(), QString());
    // Quantities chosen later are titled as usual.
    axes.setQuantities({{QStringLiteral("Current speed"), QStringLiteral("r/min")}});
    axes.fitTitles(1000);
    EXPECT_EQ(axes.axis(0)->titleText(), QStringLiteral("Current speed [r/min]"));
}
