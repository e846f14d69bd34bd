#pragma once

#include "model/run/ExitCheck.h"

#include <QCoreApplication>
#include <QStringList>
#include <QVector>

namespace opentop {

// What leaving a bus (quit, close, disconnect, connect elsewhere) does to the drives the
// program would leave behind (ExitCheck), for each choice of the exit question, in words that
// name every drive. The default hands the machine back as it should be: each running drive
// stopped and the stop confirmed by reading it, then each drive in communication priority given
// back to its own inputs (I/O priority, read back). A family without such a setting (the DC
// controller: its control source is chosen on the controller, manual 1.1) is stopped only.
// ExitActions carries a choice out; the window only asks and shows.
class ExitPlan
{
    Q_DECLARE_TR_FUNCTIONS(opentop::ExitPlan)
public:
    enum class Choice
    {
        StopAndGiveBack, // the default: stop, confirm, then I/O priority
        GiveBackOnly,    // I/O priority without a stop
        Leave            // leave every drive as it is
    };

    explicit ExitPlan(QVector<DriveLeftBehind> drives = {});

    bool isEmpty() const { return m_drives.isEmpty(); }
    const QVector<DriveLeftBehind>& drives() const { return m_drives; }
    // The drives to stop: running by the last status, and not from their own inputs (a drive
    // in I/O priority refuses a stop over the bus; it is named, and left to its inputs).
    QVector<int> running() const;
    // Whether any drive runs, from the bus or from its inputs.
    bool anyRunning() const;
    // The drives in communication priority that can be given back to their inputs.
    QVector<int> returnable() const;
    // The choices that differ from each other, the default first.
    QVector<Choice> choices() const;
    // The button: "Stop and give control back", "Stop the drives", "Leave them running", ...
    QString label(Choice choice) const;
    // What the choice does, for "Could not %1 every drive".
    QString actionText(Choice choice) const;

    QString title() const;
    // `leaving`: "quit", "connect elsewhere".
    QString question(const QString& leaving) const;
    // One entry per drive: what it is doing and what the default choice does to it.
    QStringList lines() const;
    // What each choice does, in a few sentences.
    QString explanation() const;

private:
    QVector<DriveLeftBehind> m_drives;
};

} // namespace opentop
