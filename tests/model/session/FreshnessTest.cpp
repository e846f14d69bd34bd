#include "model/session/Freshness.h"

#include <gtest/gtest.h>

using namespace opentop;

TEST(Freshness, LiveWithinAFewPollPeriodsStaleAfterOrWhenTheLinkIsDown)
{
    const QDateTime read = QDateTime::fromMSecsSinceEpoch(1'000'000);
    EXPECT_EQ(Freshness::of(QDateTime(), read, 200, true), Freshness::State::None);
    EXPECT_EQ(Freshness::of(read, read.addMSecs(1400), 200, true), Freshness::State::Live);
    EXPECT_EQ(Freshness::of(read, read.addMSecs(1600), 200, true), Freshness::State::Stale);
    EXPECT_EQ(Freshness::of(read, read.addMSecs(100), 200, false), Freshness::State::Stale);
    // Slow polling: three periods.
    EXPECT_EQ(Freshness::of(read, read.addMSecs(5900), 2000, true), Freshness::State::Live);
    EXPECT_EQ(Freshness::of(read, read.addMSecs(6100), 2000, true), Freshness::State::Stale);
}

TEST(Freshness, AgeTextGrowsWithTheAge)
{
    QLocale::setDefault(QLocale::c());
    const QDateTime read = QDateTime::fromMSecsSinceEpoch(1'000'000);
    EXPECT_EQ(Freshness::ageText(read, read.addMSecs(400)), QStringLiteral("0.4 s old"));
    EXPECT_EQ(Freshness::ageText(read, read.addMSecs(45000)), QStringLiteral("45 s old"));
    EXPECT_EQ(Freshness::ageText(read, read.addSecs(600)), QStringLiteral("10 min old"));
    EXPECT_TRUE(Freshness::staleText(read, read.addSecs(12)).contains(QStringLiteral("12 s old")));
    EXPECT_EQ(Freshness::staleText(QDateTime(), read), QStringLiteral("never read"));
}
