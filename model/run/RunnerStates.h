#pragma once

#include <QObject>
#include <QPointer>
#include <QString>
#include <QStringList>
#include <QVector>
#include <functional>
#include <utility>

namespace opentop {

// The states of a runner that moves a motor (the recipe steps, the tuning tests) by name, so a
// debugger, the log (opentop.model at debug) and a test can see where a run is. It is the one
// place for what every such runner needs:
// - go(): the current state is left (its timers and the answers it still waits for are dropped:
//   a late reply never acts on a state that has ended) and the next one entered;
// - after()/every(): timeouts and poll loops that belong to the state that made them;
// - guard(): a callback that runs only while the runner is still in the state that made it;
// - the motion flag: whether a command that may turn the motor was sent and no stop confirmed
//   since, so every exit (failure, cancel, limit, lost port, destroyed runner) knows whether it
//   must stop the motor first;
// - end(): no state any more; everything pending is dropped.
// States are small ints (an enum of the runner) with a name each.
class RunnerStates : public QObject
{
    Q_OBJECT
public:
    using Enter = std::function<void()>;

    explicit RunnerStates(const QString& runner, QObject* parent = nullptr);

    // Declares `state`, entered by go(state). Declared states only: go() to an unknown one is a
    // programming error (logged, and the runner ends).
    void add(int state, const char* name, Enter enter);

    // Enters `first` on the next turn of the event loop: a runner's done() never runs before
    // its start() returns.
    void start(int first);
    // Enters `first` now (a runner whose first state only sends a request and says its phase):
    // the runner's own done() must still not be called from inside it.
    void startNow(int first);
    // Leaves the current state and enters `state` now.
    void go(int state);
    // Leaves the current state; the runner is no longer in any.
    void end();

    bool isActive() const { return m_state >= 0; }
    int state() const { return m_state; }
    QString stateName() const { return nameOf(m_state); }
    QString nameOf(int state) const;
    // States entered since start(), in order (for tests and the log).
    const QStringList& trail() const { return m_trail; }

    // `f` runs only if the runner is still in the state (and the same entry of it) that made
    // the guard: late answers are dropped here.
    // An answer arriving after the runner is gone is dropped too.
    template <class F> auto guard(F f)
    {
        return [self = QPointer<RunnerStates>(this), entry = m_entry,
                f = std::move(f)](auto&&... args) {
            if (self && entry == self->m_entry && self->m_state >= 0)
                f(std::forward<decltype(args)>(args)...);
        };
    }
    // Runs `f` after `ms` if still in this state.
    void after(int ms, std::function<void()> f);
    // A poll loop of this state: `round(again)` runs now; when its answer has been handled it
    // calls again() and the next round starts on the next multiple of `periodMs` since the
    // loop began (the loop keeps its period even when an answer is slow); with `periodMs` 0,
    // at once on the next turn of the event loop (as fast as the line answers). The loop ends
    // with the state.
    void every(int periodMs, std::function<void(std::function<void()> again)> round);

    // A command that may turn the motor was sent (even unanswered: the motor may run).
    void motionSent()
    {
        m_motion = true;
        m_everMoved = true;
    }
    // The motor was confirmed stopped.
    void stopConfirmed() { m_motion = false; }
    // Every exit asks this first: true means stop the motor and confirm it before reporting.
    bool motionMayBeOn() const { return m_motion; }
    // Whether any motion command was sent since start() (stopped since or not).
    bool motionEverSent() const { return m_everMoved; }

signals:
    void entered(int state, const QString& name);

private:
    struct State
    {
        int id = -1;
        const char* name = "";
        Enter enter;
    };
    const State* find(int state) const;
    void leave();

    QString m_runner;
    QVector<State> m_states;
    int m_state = -1;
    quint64 m_entry = 0; // bumped on every go() and end(): guards compare against it
    bool m_motion = false;
    bool m_everMoved = false;
    QStringList m_trail;
};

} // namespace opentop
