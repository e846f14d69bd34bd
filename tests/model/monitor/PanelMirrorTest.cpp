// What the DBU's 5-digit panel shows, worked out from samples of the DBU profile.
#include "model/monitor/PanelMirror.h"
#include "model/monitor/DeviceMonitor.h"
#include "model/profile/ProfileRegistry.h"

#include <gtest/gtest.h>

using namespace opentop;

namespace {

const Profile& dbu()
{
    return *ProfileRegistry::builtIn().family(QStringLiteral("dbu"));
}

// A running (or stopped) DBU at 1500 r/min, SPno3 selected (driver bits 8..10 = 2), load 15 %.
MonitorSample sample(bool running, bool reverse = false)
{
    MonitorSample s;
    s.slave = 7;
    const double driver = (running ? 2 : 0) + (reverse ? 4 : 0) + (2 << 8);
    for (const auto& [name, value] : {std::pair(QStringLiteral("status.current_speed"), 1500.0),
                                      std::pair(QStringLiteral("status.load"), 15.0),
                                      std::pair(QStringLiteral("status.driver"), driver)}) {
        MonitorValue v;
        v.meta = dbu().parameter(name);
        v.value.valid = true;
        v.value.raw = v.value.number = value;
        s.values << v;
    }
    s.running = running;
    s.reverse = reverse;
    s.alarmActive = false;
    return s;
}

} // namespace

TEST(PanelMirrorTest, OnlyProfilesWithAPanelHaveAMirror)
{
    EXPECT_TRUE(PanelMirror::supported(dbu()));
    EXPECT_FALSE(
        PanelMirror::supported(*ProfileRegistry::builtIn().family(QStringLiteral("dcpid"))));
}

TEST(PanelMirrorTest, RunningShowsWhatThePanelSettingChooses)
{
    using C = PanelMirror::Content;
    const PanelMirror::Countdown countdown{1, 2, 30, 0};
    EXPECT_EQ(PanelMirror::show(dbu(), sample(true), C::MachineNumber, countdown).text,
              QStringLiteral("ID007"));
    EXPECT_EQ(PanelMirror::show(dbu(), sample(true), C::RunningData, countdown).text,
              QStringLiteral("SPno3"));
    EXPECT_EQ(PanelMirror::show(dbu(), sample(true), C::Load, countdown).text,
              QStringLiteral("LD015"));
    EXPECT_EQ(PanelMirror::show(dbu(), sample(true), C::Countdown, countdown).text,
              QStringLiteral("26-30"));
    // Without speed display settings: the motor speed, minus before a reverse one.
    EXPECT_EQ(PanelMirror::show(dbu(), sample(true, true), C::Speed, countdown).text,
              QStringLiteral("-1500"));
    // At standby the panel shows the speed whatever the setting.
    EXPECT_EQ(PanelMirror::show(dbu(), sample(false), C::Load, countdown).text,
              QStringLiteral("1500"));
}

TEST(PanelMirrorTest, DisplayUnitTextIsFittedToFiveDigits)
{
    MonitorSample s = sample(true);
    // As SpeedDisplay computes it: the panel text comes from the same rule.
    SpeedDisplay::Settings settings;
    settings.decimals = 3;
    s.currentShown = SpeedDisplay(settings).show(1500);
    EXPECT_EQ(s.currentShown->text, QStringLiteral("1500.000"));
    EXPECT_EQ(s.currentShown->panel, QStringLiteral("1500.0"));
    PanelMirror::Shown shown = PanelMirror::show(dbu(), s, PanelMirror::Content::Speed, {});
    EXPECT_EQ(shown.text, QStringLiteral("1500.0"));
    EXPECT_FALSE(shown.overflow);
    EXPECT_TRUE(shown.meaning.contains(QStringLiteral("1500.000 r/min")))
        << qPrintable(shown.meaning);
    bool overflow = false;
    EXPECT_EQ(PanelMirror::fit(QStringLiteral("-314.159"), &overflow), QStringLiteral("-314.1"));
    EXPECT_FALSE(overflow);
    EXPECT_EQ(PanelMirror::fit(QStringLiteral("123456"), &overflow), QStringLiteral("123456"));
    EXPECT_TRUE(overflow);
}

TEST(PanelMirrorTest, AnActiveAlarmShowsItsPanelCode)
{
    MonitorSample s = sample(false);
    s.alarmActive = true;
    s.activeAlarm =
        CodeEntry{7, QStringLiteral("AL007"), QStringLiteral("Overload"), {}, {}, {}, {}, {}, 0};
    const PanelMirror::Shown shown = PanelMirror::show(dbu(), s, PanelMirror::Content::Load, {});
    EXPECT_TRUE(shown.alarm);
    EXPECT_EQ(shown.text, QStringLiteral("AL007"));
    EXPECT_TRUE(shown.meaning.contains(QStringLiteral("Overload")));
}
