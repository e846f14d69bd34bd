#pragma once

#include "model/profile/CodeTable.h"
#include "model/profile/Profile.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QString>
#include <optional>

namespace opentop {

// What the bus list shows about one drive between polls: whether it answers, whether it runs
// and which way, its active alarm, its control priority, and the colour its MONITOR LED has.
// DriveStatusPoller fills it in and applies the LED rules (DriveStatusPoller::ledFor); its
// methods put it into words.
struct DriveStatus
{
    Q_DECLARE_TR_FUNCTIONS(opentop::DriveStatus)
public:
    // The DBU's own LED colours (manual, "MONITOR Status indicator"); Grey: no answer.
    enum class Led
    {
        Grey,
        Green,
        Orange,
        SkyBlue,
        Red,
        Purple,
        Blue
    };

    bool polled = false;         // at least one poll finished
    bool answered = false;       // the drive has answered a poll since the start
    int consecutiveFailures = 0; // polls in a row that could not be read
    QString error;               // the last poll's communication error
    std::optional<bool> running; // the "running" role
    std::optional<bool> reverse; // the "reverse" role (CCW)
    std::optional<bool> alarmActive;
    std::optional<qint64> alarmCode; // the newest alarm record while the alarm is active
    std::optional<CodeEntry> alarm;  // decoded by the profile's "alarm" code table
    QString priorityText;            // the "motionPriority" setting, e.g. "Communication priority"
    std::optional<bool> motionPriority; // whether it holds the value motion by bus needs
    Led led = Led::Grey;
    // The profile's entry for `led` (statusLed: colour, name, the manual's meaning and blink);
    // none for grey or a family without the table.
    std::optional<StatusLedEntry> ledEntry;
    QDateTime lastAnswer; // when the drive last answered a poll

    // Failures in a row after which a drive counts as not answering (grey, not blue).
    static constexpr int kNoAnswerAfter = 3;

    bool online() const { return polled && consecutiveFailures == 0; }
    // "online", "communication error (2 in a row)", "no answer"
    QString communicationText() const;
    // What the LED means for this drive: "Alarm AL007 Overload", "Running CW", ...
    QString ledText() const;
    // What the drive said at its last answer (alarm, running and which way, stopped), whatever
    // has happened to the communication since: for what was known when a link dropped.
    QString lastStateText() const;
    static QString ledName(Led led); // "red", "sky blue"
    // The profile's name of a light (statusLed's "light"): "red", "skyBlue"; empty for grey.
    static QString ledLight(Led led);
    // The colour's name for people: the profile's label while `shown` is the status's own light,
    // otherwise ledName(shown).
    QString ledLabel(Led shown) const;
    // What the drive's manual says of its light: "Alarm; flashes while an alarm is active";
    // empty without a profile entry.
    QString ledManualText() const;
};

} // namespace opentop
