#pragma once

#include "model/profile/SpeedDisplay.h"

#include <QCoreApplication>
#include <QString>
#include <optional>

namespace opentop {

class Profile;
struct MonitorSample;

// What a drive's own 5-digit panel shows, worked out from a monitor sample (manual, "DBU
// Series Operation Procedure"): while running, the content its "panelDisplay" setting chooses
// — speed in the display unit ("-" before a reverse speed), "ID001", "SPno1", the countdown
// "00-00" or the load "LD015"; at standby the speed; an active alarm as its panel code
// ("AL00B"). Profiles without a "panelDisplay" role have no panel to mirror.
class PanelMirror
{
    Q_DECLARE_TR_FUNCTIONS(opentop::PanelMirror)
public:
    enum class Content
    {
        Speed = 0,
        MachineNumber = 1,
        RunningData = 2,
        Countdown = 3,
        Load = 4
    };

    // The configured running-time countdown (the drive does not report the time left).
    struct Countdown
    {
        int days = 0;
        int hours = 0;
        int minutes = 0;
        int seconds = 0;
    };

    struct Shown
    {
        QString text;          // the characters on the panel: "1500", "-31.41", "ID001"
        bool alarm = false;    // the panel flashes the alarm code in red
        bool overflow = false; // the value has more digits than the panel
        QString meaning;       // for people: "Current speed 1500 r/min", "Load rate 15 %"
    };

    static constexpr int kDigits = SpeedDisplay::kPanelDigits;

    static bool supported(const Profile& profile);
    static Shown show(const Profile& profile, const MonitorSample& sample,
                      std::optional<Content> content, const Countdown& countdown);
    // `text` fitted to the panel's digits (SpeedDisplay::panelText, the one rule for it).
    static QString fit(const QString& text, bool* overflow = nullptr);
    static QString contentName(Content content);
};

} // namespace opentop
