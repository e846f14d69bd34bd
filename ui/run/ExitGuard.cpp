#include "ui/run/ExitGuard.h"

#include "model/bus/BusDrives.h"
#include "model/bus/DriveStatusPoller.h"
#include "model/run/ExitActions.h"
#include "model/run/ExitCheck.h"
#include "ui/widgets/PlainText.h"

#include <QHash>
#include <QMessageBox>
#include <QProgressDialog>
#include <QPushButton>
#include <QWidget>

namespace opentop {

namespace {
// How long leaving may wait for the first reading of the drives on a new link.
constexpr int kFreshReadLimitMs = 10000;
} // namespace

ExitGuard::ExitGuard(BusDrives* drives, DriveStatusPoller* poller, QWidget* window)
    : QObject(window)
    , m_drives(drives)
    , m_poller(poller)
    , m_window(window)
    , m_actions(new ExitActions(drives, this))
{
}

bool ExitGuard::anyUnread() const
{
    if (!m_drives->linkUp() || !m_poller->isActive())
        return false;
    for (int slave : m_drives->slaves())
        if (m_drives->session(slave) && !m_poller->status(slave).polled)
            return true;
    return false;
}

bool ExitGuard::wouldAsk() const
{
    if (!m_drives->linkUp())
        return false;
    return anyUnread() || !ExitCheck::collect(*m_drives, *m_poller).isEmpty();
}

void ExitGuard::check(const QString& leaving, std::function<void()> proceed)
{
    if (m_busy)
        return; // the answer to an earlier question is being carried out
    if (!m_drives->linkUp()) {
        // Never a stop over a dead port: the statuses are old and nothing would arrive.
        if (m_lostLink)
            m_lostLink(leaving, std::move(proceed));
        return;
    }
    if (!anyUnread()) {
        ask(leaving, std::move(proceed));
        return;
    }
    // Just connected (or reconnected): what the drives do is read before anything is offered.
    m_busy = true;
    m_poller->afterFreshCycle(
        this,
        [this, leaving, proceed] {
            m_busy = false;
            // Once: a drive that did not answer the fresh cycle is read, and named if it runs.
            if (m_drives->linkUp())
                ask(leaving, proceed);
            else
                check(leaving, proceed);
        },
        kFreshReadLimitMs);
}

void ExitGuard::ask(const QString& leaving, std::function<void()> proceed)
{
    const ExitPlan plan(ExitCheck::collect(*m_drives, *m_poller));
    if (plan.isEmpty()) {
        proceed();
        return;
    }
    QMessageBox box(QMessageBox::Warning, plan.title(), plan.question(leaving),
                    QMessageBox::NoButton, m_window);
    // The drives by their names.
    box.setTextFormat(Qt::PlainText);
    box.setInformativeText(PlainText::asWritten(plan.lines().join(QLatin1Char('\n')) +
                                                QStringLiteral("\n\n") + plan.explanation()));
    QHash<QAbstractButton*, ExitPlan::Choice> buttons;
    for (ExitPlan::Choice choice : plan.choices()) {
        QPushButton* b = box.addButton(plan.label(choice), choice == ExitPlan::Choice::Leave
                                                               ? QMessageBox::DestructiveRole
                                                               : QMessageBox::AcceptRole);
        buttons.insert(b, choice);
        if (choice == plan.choices().first())
            box.setDefaultButton(b);
    }
    QPushButton* stay = box.addButton(tr("Cancel"), QMessageBox::RejectRole);
    if (plan.choices().first() == ExitPlan::Choice::Leave)
        box.setDefaultButton(stay);
    box.setEscapeButton(stay);
    box.setObjectName(QStringLiteral("exitGuard"));
    // A link that drops meanwhile makes every choice but staying void: asked again over it.
    connect(m_drives, &BusDrives::linkChanged, &box, [&box](bool up) {
        if (!up)
            box.reject();
    });
    QMetaObject::invokeMethod(this, &ExitGuard::asking, Qt::QueuedConnection);
    box.exec();
    if (!m_drives->linkUp()) {
        check(leaving, std::move(proceed));
        return;
    }
    QAbstractButton* chosen = box.clickedButton();
    if (!chosen || !buttons.contains(chosen))
        return; // stay
    const ExitPlan::Choice choice = buttons.value(chosen);
    if (choice == ExitPlan::Choice::Leave) {
        proceed();
        return;
    }
    carryOut(plan, choice, std::move(proceed));
}

void ExitGuard::carryOut(const ExitPlan& plan, ExitPlan::Choice chosen,
                         std::function<void()> proceed)
{
    m_busy = true;
    const bool stopping = chosen == ExitPlan::Choice::StopAndGiveBack && !plan.running().isEmpty();
    const bool givingBack = chosen != ExitPlan::Choice::Leave && !plan.returnable().isEmpty();
    const QString text = !stopping ? tr("Giving control back to the drives' inputs…")
                         : givingBack
                             ? tr("Stopping the drives, then giving control back to their inputs…")
                             : tr("Stopping the drives…");
    auto* progress = new QProgressDialog(text, QString(), 0, 0, m_window);
    progress->setObjectName(QStringLiteral("exitProgress"));
    progress->setWindowModality(Qt::WindowModal);
    progress->setMinimumDuration(300);
    progress->setValue(0); // starts the 300 ms (the constructor's timer is the default 4 s)
    QPointer<QProgressDialog> guarded(progress);
    const QString action = plan.actionText(chosen);
    m_actions->leave(plan, chosen, [this, guarded, action, proceed](const QStringList& failures) {
        // Gone before any question about the result: a window left over it would hide its
        // text and take its clicks.
        delete guarded.data();
        finish(action, failures, proceed);
    });
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
    box.setInformativeText(PlainText::asWritten(failures.join(QLatin1Char('\n')))); // names drives
    QPushButton* stay = box.addButton(tr("Stay connected"), QMessageBox::RejectRole);
    box.addButton(tr("Go on anyway"), QMessageBox::DestructiveRole);
    box.setDefaultButton(stay);
    box.setEscapeButton(stay);
    box.setObjectName(QStringLiteral("exitFailures"));
    QMetaObject::invokeMethod(this, &ExitGuard::asking, Qt::QueuedConnection);
    box.exec();
    if (box.clickedButton() != stay)
        proceed();
}

} // namespace opentop
