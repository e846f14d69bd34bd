#pragma once

#include <QObject>
#include <QPointer>
#include <functional>

class QWidget;

namespace opentop {

class BusDrives;
class DriveStatusPoller;
class ExitActions;

// Stands between the user and every way out of a bus (quit, closing the window, connecting
// elsewhere) while drives run or are left in communication priority: it names them and asks
// whether to stop them (the default), give control back to their own inputs, leave them as they
// are, or stay. The chosen action runs on the bus thread with a progress window; only when it
// has succeeded, or the user accepts what failed, does `proceed` run.
class ExitGuard : public QObject
{
    Q_OBJECT
public:
    ExitGuard(BusDrives* drives, DriveStatusPoller* poller, QWidget* window);

    // `leaving`: what the user is about to do, for the question ("quit", "connect elsewhere").
    // Calls `proceed` at once when nothing would be left behind.
    void check(const QString& leaving, std::function<void()> proceed);
    bool isBusy() const { return m_busy; }

signals:
    // The question is on screen (tests answer it through QApplication::activeModalWidget()).
    void asking();

private:
    void finish(const QString& action, const QStringList& failures, std::function<void()> proceed);

    BusDrives* m_drives;
    DriveStatusPoller* m_poller;
    QPointer<QWidget> m_window;
    ExitActions* m_actions;
    bool m_busy = false;
};

} // namespace opentop
