#pragma once

#include "model/eol/RecipeTypes.h"
#include "model/eol/StepMeasure.h"
#include "model/eol/UnitRecord.h"
#include "model/run/RunControl.h"
#include "model/run/RunnerStates.h"
#include "model/run/StopConfirmer.h"

#include <QObject>
#include <QPointer>
#include <functional>
#include <optional>

namespace opentop {

class DeviceSession;

// Runs one drive's recipe steps (docs/recipe-format.md, "Steps"): priority, running data,
// speed command, start, wait for speed, hold while measuring, no alarm, stop, read. Motion
// happens only in these steps. Each measured value is compared with its limits as it is
// taken (StepMeasure); the first failure, an alarm while running or abort() stops the motor at
// once and confirms it stopped (StopConfirmer). Communication priority taken by a priority step
// is given back, as the drive held it, once the motor has stopped.
//
// A state machine (RunnerStates): one state per kind of step, then the exits. Every way out (a
// failure, a limit, abort(), a lost session) goes through fail(): Stopping when motion may be
// on, GivingBack when priority was taken, then Finished, which reports.
class EolStepRunner : public QObject
{
    Q_OBJECT
public:
    struct Timing
    {
        int pollMs = 100; // live values during wait and hold
        int maxFailedPolls = 5;
        StopConfirmer::Timing stop;
    };
    struct Result
    {
        bool ok = false;
        QString failure;           // the first failure, in words (names the step)
        bool stopConfirmed = true; // false: motion may have begun and no stop was confirmed
        QString stopDetail;        // what became of the motor after a failure or abort
    };
    using Done = std::function<void(const Result&)>;

    EolStepRunner(DeviceSession* session, RunControl* run, const QVector<RecipeStep>& steps,
                  const Timing& timing, QObject* parent = nullptr);
    // Deleted while the motor may turn: the stop is sent, not waited for.
    ~EolStepRunner() override;
    // `done` runs once, never before start() returns.
    void start(Done done);
    // Ends the steps with `reason`: the motor is stopped and the stop confirmed first when
    // motion may have begun.
    void abort(const QString& reason) { fail(reason); }
    bool isRunning() const { return bool(m_done); }
    // Where the steps are and the states entered so far (tests, the log).
    const RunnerStates& states() const { return m_states; }

signals:
    void stepStarted(int index, const QString& title);
    void measured(const opentop::Measurement& measurement);
    // The current speed as read during wait and hold steps.
    void speedSampled(double speed, const QString& unit);

private:
    enum State
    {
        Priority, // take communication priority, keeping the drive's own
        Command,  // select, speed and start steps: their run commands
        WaitSpeed,
        Hold,
        NoAlarm,
        StopStep, // the recipe's stop, timed against its deceleration
        Read,
        // The exits, last (exiting() relies on it).
        Stopping,   // after a failure: stop the motor and confirm it
        GivingBack, // the priority as the drive held it
        Finished    // the result reported
    };
    using Stopped = std::function<void(bool confirmed, const QString& detail, qint64 ms)>;

    void addStates();
    static State stateOf(const RecipeStep& step);
    void enterStep(State state, const std::function<void(const RecipeStep&)>& run);
    void next();
    void verdict(const QString& failure); // a step's: empty goes on, else fails
    void runPriority();
    void runCommands(const RecipeStep& step);
    void sendCommands(QVector<RunControl::Command> commands);
    void runStop(const RecipeStep& step);
    void stopMotor(int marginMs, Stopped then);
    void fail(const QString& reason);
    bool exiting() const { return m_states.state() >= Stopping; }
    State afterStop() const { return m_priorityBefore ? GivingBack : Finished; }
    void enterStopping();
    void enterGivingBack();
    void enterDone();
    QString stepText() const;
    template <class F> auto answer(F f) { return StepMeasure::answer(m_states, std::move(f)); }

    QPointer<DeviceSession> m_session;
    RunControl* m_run;
    QVector<RecipeStep> m_steps;
    Timing m_timing;
    RunnerStates m_states;
    StepMeasure m_measure;
    Done m_done;
    Result m_result;
    int m_index = -1;
    int m_selected = 0;                      // running data selected by a select step
    std::optional<QString> m_priorityBefore; // the priority setting before the priority step
};

} // namespace opentop
