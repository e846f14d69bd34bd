#include "model/run/LinkLoss.h"

#include "model/bus/BusDrives.h"
#include "model/bus/DriveStatusPoller.h"
#include "model/session/Freshness.h"

#include <QLocale>
#include <algorithm>

namespace opentop {

namespace {

QString clockText(const QDateTime& time)
{
    return QLocale().toString(time.toLocalTime().time(), QStringLiteral("HH:mm:ss"));
}

} // namespace

LinkLoss LinkLoss::take(const BusDrives& drives, const DriveStatusPoller& poller,
                        const QString& place, const QDateTime& at)
{
    LinkLoss loss;
    loss.m_place = place;
    loss.m_at = at;
    loss.m_drives = ExitCheck::collect(drives, poller);
    for (int slave : drives.slaves()) {
        // A drive identified but never read may be running: it is named too.
        if (drives.session(slave) && !poller.status(slave).answered)
            loss.m_unknown << tr("Machine number %1 (%2): state never read")
                                  .arg(slave)
                                  .arg(drives.info(slave).shortModel());
    }
    return loss;
}

bool LinkLoss::anyRunning() const
{
    return std::any_of(m_drives.begin(), m_drives.end(),
                       [](const DriveLeftBehind& d) { return d.running; });
}

QString LinkLoss::headline() const
{
    return tr("The connection to %1 was lost at %2.").arg(m_place, clockText(m_at));
}

QString LinkLoss::driveLines() const
{
    QStringList lines;
    for (const DriveLeftBehind& d : m_drives) {
        // The age is the reading's when the link dropped: later it only gets older.
        lines << tr("• %1 — last answer %2 (%3 when the link dropped)")
                     .arg(d.text(), clockText(d.lastAnswer),
                          Freshness::ageText(d.lastAnswer, m_at));
    }
    for (const QString& unknown : m_unknown)
        lines << QStringLiteral("• ") + unknown;
    if (lines.isEmpty())
        return tr("By the last values read, no drive was running or in communication priority.");
    return tr("When the link dropped, by the last values read:") + QLatin1Char('\n') +
           lines.join(QLatin1Char('\n'));
}

QString LinkLoss::whatToCheck() const
{
    if (!leavesAnything())
        return {};
    return tr("OpenTOP cannot stop these drives or give control back to their inputs until the "
              "link is back: nothing is sent over a lost link. A drive in communication priority "
              "keeps its last command. Check on the machine: each drive's own STOP input, the "
              "emergency stop, and the drives' power.");
}

QString LinkLoss::exitQuestion(const QString& leaving) const
{
    return tr("Before you %1: the connection to %2 was lost at %3, and OpenTOP cannot reach these "
              "drives.")
        .arg(leaving, m_place, clockText(m_at));
}

QString LinkLoss::summary() const
{
    QStringList running;
    QStringList priority;
    for (const DriveLeftBehind& d : m_drives) {
        const QString drive = QStringLiteral("%1 (%2)").arg(d.slave).arg(d.model);
        if (d.running)
            running << drive;
        else
            priority << drive;
    }
    QStringList parts{headline()};
    if (!running.isEmpty())
        parts << tr("Running when it dropped, by the last values read: machine number %1.")
                     .arg(running.join(QStringLiteral(", ")));
    if (!priority.isEmpty())
        parts << tr("In communication priority: machine number %1.")
                     .arg(priority.join(QStringLiteral(", ")));
    if (!m_unknown.isEmpty())
        parts << tr("%n drive(s) never read.", nullptr, int(m_unknown.size()));
    if (leavesAnything())
        parts << tr("OpenTOP cannot stop them until the link is back: check each drive's STOP "
                    "input, the emergency stop and the power on the machine.");
    return parts.join(QLatin1Char(' '));
}

QString LinkLoss::readAgain(const BusDrives& drives, const DriveStatusPoller& poller,
                            bool* attention)
{
    QStringList lines;
    for (const DriveLeftBehind& d : ExitCheck::collect(drives, poller))
        lines << QStringLiteral("• ") + d.text();
    for (int slave : drives.slaves()) {
        const DriveStatus status = poller.status(slave);
        if (drives.session(slave) && (!status.polled || !status.online()))
            lines << QStringLiteral("• ") + tr("Machine number %1 (%2): no answer, its state is "
                                               "not known")
                                                .arg(slave)
                                                .arg(drives.info(slave).shortModel());
    }
    if (attention)
        *attention = !lines.isEmpty();
    if (lines.isEmpty())
        return tr("Every drive read again: none is running or in communication priority.");
    return tr("Read again just now:") + QLatin1Char('\n') + lines.join(QLatin1Char('\n'));
}

} // namespace opentop
