#include "model/bus/DriveStatus.h"

namespace opentop {

QString DriveStatus::communicationText() const
{
    if (!polled)
        return tr("not polled yet");
    if (consecutiveFailures == 0)
        return tr("online");
    if (!answered || consecutiveFailures >= kNoAnswerAfter)
        return tr("no answer (%n poll(s) in a row)", nullptr, consecutiveFailures);
    return tr("communication error (%n in a row)", nullptr, consecutiveFailures);
}

QString DriveStatus::ledText() const
{
    if (!polled)
        return tr("Status not known yet");
    if (led == Led::Grey)
        return tr("No answer: %1").arg(error);
    // An alarm outranks a communication error (as the LED shows it).
    if (consecutiveFailures > 0 && !alarmActive.value_or(false))
        return tr("Communication error: %1").arg(error);
    return lastStateText();
}

QString DriveStatus::lastStateText() const
{
    if (!answered)
        return tr("Status not known yet");
    if (alarmActive.value_or(false)) {
        if (alarm)
            return tr("Alarm %1 %2").arg(alarm->panel, alarm->name);
        if (alarmCode)
            return tr("Alarm %1h (not in the alarm table)")
                .arg(QString::number(*alarmCode, 16).toUpper());
        return tr("Alarm active");
    }
    if (running.value_or(false)) {
        if (!reverse)
            return tr("Running");
        return *reverse ? tr("Running CCW") : tr("Running CW");
    }
    return tr("Stopped, no alarm");
}

QString DriveStatus::ledName(Led led)
{
    switch (led) {
    case Led::Grey:
        return tr("grey");
    case Led::Green:
        return tr("green");
    case Led::Orange:
        return tr("orange");
    case Led::SkyBlue:
        return tr("sky blue");
    case Led::Red:
        return tr("red");
    case Led::Purple:
        return tr("purple");
    case Led::Blue:
        return tr("blue");
    }
    return QString();
}

QString DriveStatus::ledLight(Led led)
{
    switch (led) {
    case Led::Grey:
        return QString();
    case Led::Green:
        return QStringLiteral("green");
    case Led::Orange:
        return QStringLiteral("orange");
    case Led::SkyBlue:
        return QStringLiteral("skyBlue");
    case Led::Red:
        return QStringLiteral("red");
    case Led::Purple:
        return QStringLiteral("purple");
    case Led::Blue:
        return QStringLiteral("blue");
    }
    return QString();
}

QString DriveStatus::ledLabel(Led shown) const
{
    return ledEntry && shown == led ? ledEntry->label : ledName(shown);
}

QString DriveStatus::ledManualText() const
{
    if (!ledEntry)
        return QString();
    if (ledEntry->blink.isEmpty())
        return ledEntry->meaning;
    return tr("%1; %2").arg(ledEntry->meaning, ledEntry->blink);
}

} // namespace opentop
