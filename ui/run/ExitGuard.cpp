#include "run/ExitGuard.h"

#include "run/ExitActions.h"
#include "run/ExitCheck.h"

#include <QMessageBox>
#include <QProgressDialog>
#include <QPushButton>
#include <QWidget>

namespace opentop {

ExitGuard::ExitGuard(BusDrives* drives, DriveStatusPoller* poller, QWidget* window)
    : QObject(window)
    , m_drives(drives)
    , m_poller(poller)
    , m_window(window)
    , m_actions(new ExitActions(drives, this))
{
}

void ExitGuard::check(const QString& leaving, std::function<void()> proceed)
{
    if (m_busy)
        return; // the answer to an earlier question is being carried out
    const QVector<DriveLeftBehind> left = ExitCheck::collect(*m_drives, *m_poller);
    if (left.isEmpty()) {
        proceed();
        return;
    }
    QVector<int> running;
    QVector<int> returnable;
    QStringList lines;
    for (const DriveLeftBehind& d : left) {
        lines << QStringLiteral("• ") + d.text();
        if (d.running)
            running << d.slave;
        if (d.busPriority && d.canReturn)
            returnable << d.slave;
    }

    QMessageBox box(
        QMessageBox::Warning,
        running.isEmpty() ? tr("Drives left in communication priority") : tr("Drives are running"),
        running.isEmpty()
            ? tr("Before you %1: these drives are left in communication priority.").arg(leaving)
            : tr("Before you %1: these drives are running or left in communication "
                 "priority.")
                  .arg(leaving),
        QMessageBox::NoButton, m_window);
    QString explanation = tr("In communication priority a drive takes run and stop only from the "
                             "bus: once OpenTOP lets go, only another bus master or switching its "
                             "power off stops it.");
    if (!running.isEmpty())
        explanation += QLatin1Char(' ') + tr("\"Stop\" broadcasts every family's stop command to "
                                             "the whole bus and checks that each drive above has "
                                             "stopped.");
    if (!returnable.isEmpty())
        explanation += QLatin1Char(' ') + tr("\"Give control back\" sets I/O priority, so the "
                                             "machine's own inputs run the drives again.");
    box.setInformativeText(lines.join(QLatin1Char('\n')) + QStringLiteral("\n\n") + explanation);
    QPushButton* stop =
        running.isEmpty() ? nullptr : box.addButton(tr("Stop the drives"), QMessageBox::AcceptRole);
    QPushButton* giveBack =
        returnable.isEmpty()
            ? nullptr
            : box.addButton(tr("Give control back (I/O priority)"), QMessageBox::AcceptRole);
    QPushButton* leave =
        box.addButton(running.isEmpty() ? tr("Leave them so") : tr("Leave them running"),
                      QMessageBox::DestructiveRole);
    QPushButton* stay = box.addButton(tr("Cancel"), QMessageBox::RejectRole);
    box.setDefaultButton(stop ? stop : giveBack ? giveBack : stay);
    box.setEscapeButton(stay);
    box.setObjectName(QStringLiteral("exitGuard"));
    QMetaObject::invokeMethod(this, &ExitGuard::asking, Qt::QueuedConnection);
    box.exec();
    QAbstractButton* chosen = box.clickedButton();
    if (!chosen || chosen == stay)
        return;
    if (chosen == leave) {
        proceed();
        return;
    }

    m_busy = true;
    const bool stopping = chosen == stop;
    auto* progress = new QProgressDialog(
        stopping ? tr("Stopping the drives…") : tr("Giving control back to the drives' inputs…"),
        QString(), 0, 0, m_window);
    progress->setObjectName(QStringLiteral("exitProgress"));
    progress->setWindowModality(Qt::WindowModal);
    progress->setMinimumDuration(300);
    QPointer<QProgressDialog> guarded(progress);
    auto done = [this, guarded, stopping, proceed](const QStringList& failures) {
        if (guarded)
            guarded->deleteLater();
        finish(stopping ? tr("stop") : tr("give control back"), failures, proceed);
    };
    if (stopping)
        m_actions->stop(running, done);
    else
        m_actions->returnToIoPriority(returnable, done);
}

void ExitGuard::finish(const QString& action, const QStringList& failures,
                       std::function<void()> proceed)
{
    m_busy = false;
    if (failures.isEmpty()) {
        proceed();
        return;
    }
    QMessageBox box(QMessageBox::Critical, tr("Not every drive is safe"),
                    tr("Could not %1 every drive:").arg(action), QMessageBox::NoButton, m_window);
    box.setInformativeText(failures.join(QLatin1Char('\n')));
    QPushButton* stay = box.addButton(tr("Stay connected"), QMessageBox::RejectRole);
    box.addButton(tr("Go on anyway"), QMessageBox::DestructiveRole);
    box.setDefaultButton(stay);
    box.setEscapeButton(stay);
    box.setObjectName(QStringLiteral("exitFailures"));
    box.exec();
    if (box.clickedButton() != stay)
        proceed();
}

} // namespace opentop
