#include "model/run/ExitPlan.h"

#include <algorithm>

namespace opentop {

ExitPlan::ExitPlan(QVector<DriveLeftBehind> drives)
    : m_drives(std::move(drives))
{
}

QVector<int> ExitPlan::running() const
{
    QVector<int> out;
    for (const DriveLeftBehind& d : m_drives)
        if (d.running && !d.inputsControl)
            out << d.slave;
    return out;
}

bool ExitPlan::anyRunning() const
{
    return std::any_of(m_drives.begin(), m_drives.end(),
                       [](const DriveLeftBehind& d) { return d.running; });
}

QVector<int> ExitPlan::returnable() const
{
    QVector<int> out;
    for (const DriveLeftBehind& d : m_drives)
        if (d.busPriority && d.canReturn)
            out << d.slave;
    return out;
}

QVector<ExitPlan::Choice> ExitPlan::choices() const
{
    QVector<Choice> out;
    if (!running().isEmpty() || !returnable().isEmpty())
        out << Choice::StopAndGiveBack;
    // Without a running drive the default gives control back only: the same choice.
    if (!running().isEmpty() && !returnable().isEmpty())
        out << Choice::GiveBackOnly;
    out << Choice::Leave;
    return out;
}

QString ExitPlan::label(Choice choice) const
{
    const bool stop = !running().isEmpty();
    const bool giveBack = !returnable().isEmpty();
    switch (choice) {
    case Choice::StopAndGiveBack:
        if (stop && giveBack)
            return tr("Stop and give control back");
        return stop ? tr("Stop the drives") : tr("Give control back (I/O priority)");
    case Choice::GiveBackOnly:
        return tr("Give control back only");
    case Choice::Leave:
        return anyRunning() ? tr("Leave them running") : tr("Leave them so");
    }
    return {};
}

QString ExitPlan::actionText(Choice choice) const
{
    switch (choice) {
    case Choice::StopAndGiveBack:
        if (running().isEmpty())
            return tr("give control back to");
        return returnable().isEmpty() ? tr("stop") : tr("stop and give control back to");
    case Choice::GiveBackOnly:
        return tr("give control back to");
    case Choice::Leave:
        break;
    }
    return {};
}

QString ExitPlan::title() const
{
    return anyRunning() ? tr("Drives are running") : tr("Drives left in communication priority");
}

QString ExitPlan::question(const QString& leaving) const
{
    return !anyRunning()
               ? tr("Before you %1: these drives are left in communication priority.").arg(leaving)
               : tr("Before you %1: these drives are running or left in communication "
                    "priority.")
                     .arg(leaving);
}

QStringList ExitPlan::lines() const
{
    QStringList out;
    for (const DriveLeftBehind& d : m_drives) {
        const bool giveBack = d.busPriority && d.canReturn;
        QString what;
        if (d.running && d.inputsControl)
            what = tr("left as it is: it runs from its own inputs (I/O priority), which a stop "
                      "over the bus does not override");
        else if (d.running && giveBack)
            what = tr("stopped (confirmed by reading it), then given back to its own inputs (I/O "
                      "priority, read back)");
        else if (d.running && !d.canReturn)
            what = tr("stopped (confirmed by reading it); its family has no I/O priority setting, "
                      "so it stays under the bus's control");
        else if (d.running)
            what = tr("stopped (confirmed by reading it)");
        else if (giveBack)
            what = tr("given back to its own inputs (I/O priority, read back)");
        else
            what = tr("left as it is: no way to give control back to its inputs is known");
        out << QStringLiteral("• ") + d.text() + QLatin1Char('\n') + tr("   → %1").arg(what);
    }
    return out;
}

QString ExitPlan::explanation() const
{
    QString text = tr("In communication priority a drive takes run and stop only from the bus: "
                      "once OpenTOP lets go, only another bus master or switching its power off "
                      "stops it.");
    if (!running().isEmpty())
        text += QLatin1Char(' ') + tr("Stopping broadcasts every family's stop command to the "
                                      "whole bus and checks that each drive above has stopped; a "
                                      "drive that has not stopped is not given back to its "
                                      "inputs.");
    if (!running().isEmpty() && !returnable().isEmpty())
        text += QLatin1Char(' ') + tr("\"Give control back only\" sets I/O priority without a "
                                      "stop: the machine's own inputs decide at once whether the "
                                      "drives run.");
    else if (!returnable().isEmpty())
        text += QLatin1Char(' ') + tr("\"Give control back\" sets I/O priority, so the machine's "
                                      "own inputs run the drives again.");
    return text;
}

} // namespace opentop
