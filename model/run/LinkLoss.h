#pragma once

#include "model/run/ExitCheck.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QStringList>
#include <QVector>

namespace opentop {

class BusDrives;
class DriveStatusPoller;

// What the program knew of the drives when the link to their bus dropped: the drives running
// or left in communication priority by the last values read, each with the age of what is
// known, and the drives whose state was never read. Nothing can be sent over a dead link, so
// nothing that would need it is offered: the user is told what to check on the machine.
class LinkLoss
{
    Q_DECLARE_TR_FUNCTIONS(opentop::LinkLoss)
public:
    LinkLoss() = default;
    // Taken when the link drops. `place`: the connection as the user knows it ("/dev/ttyUSB0").
    static LinkLoss take(const BusDrives& drives, const DriveStatusPoller& poller,
                         const QString& place,
                         const QDateTime& at = QDateTime::currentDateTimeUtc());

    bool isValid() const { return m_at.isValid(); }
    QDateTime at() const { return m_at; }
    QString place() const { return m_place; }
    // Running or in communication priority by the last values read.
    const QVector<DriveLeftBehind>& drives() const { return m_drives; }
    // "Machine number 7 (DC PID): state never read": drives whose state was never read.
    const QStringList& unknown() const { return m_unknown; }
    bool anyRunning() const;
    // Whether anything may have been left behind: drives above, or drives never read.
    bool leavesAnything() const { return !m_drives.isEmpty() || !m_unknown.isEmpty(); }

    // "The connection to /dev/ttyUSB0 was lost at 10:32:05."
    QString headline() const;
    // One line per drive as last read, with the age of that reading when the link dropped;
    // a sentence when no drive was running or in communication priority.
    QString driveLines() const;
    // That nothing can be stopped over the lost link, and what to check on the machine.
    QString whatToCheck() const;
    // The question before leaving (`leaving`: "quit", "connect elsewhere").
    QString exitQuestion(const QString& leaving) const;
    // For a bar: the headline, the drives running or in communication priority by number, and
    // what to check on the machine, in one paragraph.
    QString summary() const;

    // After reconnecting, once every drive has been read again: the drives running or in
    // communication priority now and the ones that did not answer, one line each; `attention`
    // says whether there are any.
    static QString readAgain(const BusDrives& drives, const DriveStatusPoller& poller,
                             bool* attention = nullptr);

private:
    QString m_place;
    QDateTime m_at;
    QVector<DriveLeftBehind> m_drives;
    QStringList m_unknown;
};

} // namespace opentop
