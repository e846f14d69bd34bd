// Value axis titles of a trend chart: full when they fit, shortened so the unit stays.
#include "trends/TrendAxes.h"

#include <QChart>
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
    axes.fitTitles(60); // far too short for either full title
    EXPECT_EQ(axes.axis(0)->titleText(), QStringLiteral("Speed [r/min]"));
    EXPECT_EQ(axes.axis(1)->titleText(), QStringLiteral("[%]"));
    EXPECT_EQ(TrendAxes::sharedWord({QStringLiteral("Motor current"), QStringLiteral("PWM duty")}),
              QString());
}
