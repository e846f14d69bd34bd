#pragma once

#include <QObject>
#include <functional>

namespace opentop {

class BusDrives;
class DriveStatusPoller;
class ExitGuard;
class MainWindow;

// Every way out of the window's bus (quitting, Bus ▸ Disconnect, connecting elsewhere) asks
// here first: a unit under test on the operator screen is ended (its motors stopped, then the
// drives' status read again); on quitting, edits not written are named; then the exit question
// over a live link (ExitGuard, made per connection) or the lost link's (Reconnection).
class BusLeaving : public QObject
{
    Q_OBJECT
public:
    explicit BusLeaving(MainWindow* window);

    // The exit question of a new connection's drives; release() lets it go with them.
    void watch(BusDrives* drives, DriveStatusPoller* poller);
    void release();
    ExitGuard* exitGuard() const { return m_exitGuard; }

    // A unit being tested is ended first, if the user agrees: true when it was asked, and
    // `retry` then runs once the drives' status has been read again.
    bool unitHolds(const QString& leaving, std::function<void()> retry);
    // The exit question over a live link, the lost link's over a dead one; `proceed` when
    // answered.
    void check(const QString& leaving, std::function<void()> proceed);
    // Whether the window may close now; when not, it asks (and closes again once answered).
    bool mayClose();

private:
    std::function<void()> freshStatusThen(std::function<void()> then);

    MainWindow* m_window;
    ExitGuard* m_exitGuard = nullptr;
    bool m_leavingChecked = false; // the user has answered the exit question: close now
};

} // namespace opentop
