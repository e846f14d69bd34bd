#pragma once

#include "model/run/ExitPlan.h"

#include <QObject>
#include <QPointer>
#include <functional>

class QWidget;

namespace opentop {

class BusDrives;
class DriveStatusPoller;
class ExitActions;

// Stands between the user and every way out of a bus (quit, closing the window, disconnecting,
// connecting elsewhere) while drives run or are left in communication priority: it names each
// drive and what will happen to it (ExitPlan) and asks whether to stop them and give control
// back to their inputs (the default), give control back only, leave them as they are, or stay.
// The choice is carried out by the model (ExitActions) with a progress window, which closes
// before any question about its result; only when it has succeeded, or the user accepts what
// failed, does `proceed` run. Over a lost link it attempts nothing: the question is the lost
// link's (setLostLinkQuestion: the main window's Reconnection).
class ExitGuard : public QObject
{
    Q_OBJECT
public:
    ExitGuard(BusDrives* drives, DriveStatusPoller* poller, QWidget* window);

    // `leaving`: what the user is about to do, for the question ("quit", "connect elsewhere").
    // Calls `proceed` at once when nothing would be left behind.
    void check(const QString& leaving, std::function<void()> proceed);
    bool isBusy() const { return m_busy; }
    // Whether check() would ask (or first read the drives' state, not read yet on this link);
    // false while the link is down (the lost link's question is another's).
    bool wouldAsk() const;
    // Asks instead of check() while the link is down: nothing can be stopped over it.
    using Question = std::function<void(const QString& leaving, std::function<void()> proceed)>;
    void setLostLinkQuestion(Question question) { m_lostLink = std::move(question); }

signals:
    // The question is on screen (tests answer it through QApplication::activeModalWidget()).
    void asking();

private:
    bool anyUnread() const;
    void ask(const QString& leaving, std::function<void()> proceed);
    void carryOut(const ExitPlan& plan, ExitPlan::Choice choice, std::function<void()> proceed);
    void finish(const QString& action, const QStringList& failures, std::function<void()> proceed);

    BusDrives* m_drives;
    DriveStatusPoller* m_poller;
    QPointer<QWidget> m_window;
    ExitActions* m_actions;
    Question m_lostLink;
    bool m_busy = false;
};

} // namespace opentop
