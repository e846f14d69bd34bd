#include "ui/main/BusLeaving.h"

#include "model/bus/BusDrives.h"
#include "model/bus/DriveStatusPoller.h"
#include "model/session/DeviceParameters.h"
#include "ui/eol/ProductionMode.h"
#include "ui/main/MainWindow.h"
#include "ui/main/Reconnection.h"
#include "ui/run/ExitGuard.h"

#include <QMessageBox>
#include <QTimer>

namespace opentop {

BusLeaving::BusLeaving(MainWindow* window)
    : QObject(window)
    , m_window(window)
{
}

void BusLeaving::watch(BusDrives* drives, DriveStatusPoller* poller)
{
    // No way out of this bus (quit, another connection) leaves a motor running unannounced.
    m_exitGuard = new ExitGuard(drives, poller, m_window);
    m_exitGuard->setLostLinkQuestion(
        [window = m_window](const QString& leaving, std::function<void()> proceed) {
            window->reconnection()->askLeaving(leaving, std::move(proceed));
        });
}

void BusLeaving::release()
{
    if (m_exitGuard) {
        m_exitGuard->deleteLater(); // its answer may be what brought us here
        m_exitGuard = nullptr;
    }
}

std::function<void()> BusLeaving::freshStatusThen(std::function<void()> then)
{
    // After a unit is cancelled, the drives' status must be read again before the exit check
    // looks at it: the run has just stopped its motors.
    return [window = m_window, then = std::move(then)] {
        if (DriveStatusPoller* poller = window->statusPoller())
            poller->afterFreshCycle(window, then);
        else
            then();
    };
}

bool BusLeaving::unitHolds(const QString& leaving, std::function<void()> retry)
{
    ProductionMode* production = m_window->production();
    return production && production->guard(leaving, freshStatusThen(std::move(retry)));
}

void BusLeaving::check(const QString& leaving, std::function<void()> proceed)
{
    if (m_exitGuard)
        m_exitGuard->check(leaving, std::move(proceed));
    else // no bus, or one that never came back: only what the lost link left behind is asked
        m_window->reconnection()->askLeaving(leaving, std::move(proceed));
}

bool BusLeaving::mayClose()
{
    if (unitHolds(tr("quit"), [window = m_window] { window->close(); }))
        return false;
    int pending = 0;
    if (BusDrives* drives = m_window->drives()) {
        for (int s : drives->slaves())
            pending += drives->parameters(s) ? drives->parameters(s)->pendingNames().size() : 0;
    }
    if (pending > 0 &&
        QMessageBox::question(
            m_window, tr("Unwritten changes"),
            tr("%n edit(s) have not been written to the drives. Quit and discard them?", nullptr,
               pending),
            QMessageBox::Discard | QMessageBox::Cancel,
            QMessageBox::Cancel) != QMessageBox::Discard)
        return false;
    // Drives running or left in communication priority, or left so when the link dropped: ask
    // first (outside the close event).
    if (!m_leavingChecked &&
        ((m_exitGuard && m_exitGuard->wouldAsk()) || m_window->reconnection()->wouldAsk())) {
        QTimer::singleShot(0, m_window, [this] {
            check(tr("quit"), [this] {
                m_leavingChecked = true;
                m_window->close();
            });
        });
        return false;
    }
    return true;
}

} // namespace opentop
