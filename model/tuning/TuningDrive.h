#pragma once

#include "model/run/RunnerStates.h"
#include "model/session/DeviceSession.h"
#include "model/tuning/TuningRunner.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <functional>
#include <optional>

namespace opentop {

// What the step test and the relay autotune do on the drive, and the states every test begins
// and ends with. A test's run: Prepare (the speed mode, communication-loss time, gains and
// current limit read; outside a closed-loop mode it is refused before anything moves), then
// SetCommLoss (the braking time the test runs with), then the test's own states (added to
// states() by StepTest and RelayAutotune), then the one exit of every end (success, cancel, a
// limit, a lost port): StopMotor (when motion may be on: speed command 0 and readings until the
// motor stands), RestoreMode and RestoreCommLoss (what the test changed), Reported (the result
// handed over). In between the tests ask it for readings (checked against the limits and cancel),
// the speed command and the mode. A drive gone mid-test sends the stop without waiting.
class TuningDrive : public QObject
{
    Q_OBJECT
public:
    using Result = TuningRunner::Result;
    using Done = TuningRunner::Done;
    using Limits = TuningRunner::Limits;
    // The tests' own states follow: StepTest's from 10, RelayAutotune's from 20.
    enum State
    {
        Prepare,
        SetCommLoss,
        StopMotor,
        RestoreMode,
        RestoreCommLoss,
        Reported,
    };

    TuningDrive(DeviceSession* session, const TuningSpec& spec, QObject* parent = nullptr);
    ~TuningDrive() override;

    DeviceSession* session() const { return m_session; }
    const TuningSpec& spec() const { return m_spec; }
    void setLimits(const Limits& limits) { m_limits = limits; }
    const Limits& limits() const { return m_limits; }
    void setClock(std::function<double()> nowMs) { m_clock = std::move(nowMs); }
    RunnerStates& states() { return *m_states; }

    // Only one test at a time: true (and `done` told so on the next turn) while one runs.
    bool refuseIfRunning(const Done& done);
    // Starts a test: Prepare, SetCommLoss when needed, then `first` (the test's own state).
    void begin(Done done, int first);
    bool isRunning() const { return bool(m_done); }
    // In the exit's states: readings are no longer checked, failures no longer end the test.
    bool exiting() const;
    // Ends the test at the next reading (as a limit does).
    void cancel();
    // The exit, with `error` (aborted: stopped by a limit, cancel or a failure) or as it is.
    void fail(const QString& error, bool aborted = true);
    void finish();

    // A reading of speed, current and output, stamped since reference(); beyond a limit or
    // after cancel() the test fails instead. Five failed in a row end the test, or in the exit
    // call `lost` (waiting for the stop on a line that is gone: it cannot be confirmed).
    void poll(std::function<void(const TuningSample&)> then, std::function<void()> lost = {});
    // The speed command in the present mode's engineering units, rounded to its raw steps.
    void command(double engineering, std::function<void()> then);
    // The speed mode; restored at the exit.
    void setMode(int mode, std::function<void()> then);
    void announce(const QString& text) { emit phase(text); }
    // A reading the test keeps: into the result's samples and out as sampled().
    void record(const TuningSample& sample);

    Result& result() { return m_run.result; }
    double nowMs() const;
    // The moment samples are stamped from (the step, a hold, the relay's start), ms since begin.
    double reference() const { return m_run.t0; }
    void setReference(double ms) { m_run.t0 = ms; }
    // Engineering per raw of the speed command in the mode the drive is in now.
    double feedbackScale() const;
    double closedScale() const { return m_run.closedScale; }
    std::optional<double> originalMode() const { return m_run.originalMode; }
    double currentLimit() const { return m_run.currentLimit; }

signals:
    void sampled(const opentop::TuningSample& sample);
    void phase(const QString& text);

private:
    static constexpr int kMaxFailedPolls = 5;
    // One test's values, all reset by begin().
    struct Run
    {
        Result result;
        int first = -1; // the test's own first state
        QElapsedTimer clock;
        double origin = 0; // the clock at begin(), when one was set
        double t0 = 0;
        std::optional<double> originalMode;
        std::optional<double> originalCommLoss;
        bool modeChanged = false;
        bool commLossChanged = false;
        bool cancelled = false;
        int failedPolls = 0;
        double closedScale = 1;  // engineering per raw of the closed-loop speed command
        double currentLimit = 0; // A, the drive's (0: unknown)
        bool stopSent = false;
        double stopUntilMs = 0;
    };

    // A session's answer to the present state: dropped once the state has ended (a late
    // answer) or the drive is gone.
    template <class F> auto answer(F f)
    {
        return [alive = QPointer<RunnerStates>(m_states),
                g = m_states->guard(std::move(f))](const auto& outcome) {
            if (alive)
                g(outcome);
        };
    }
    void prepare();
    void prepared(const DeviceSession::ReadManyOutcome& r);
    QString notClosedLoop() const;
    void setCommLoss();
    void stopMotor();
    void waitStopped();
    void stopped(bool atRest);
    void restoreOrReport(bool modeRestored);
    void report();
    void writeNumber(const QString& parameter, double value, std::function<void(bool)> then);

    DeviceSession* m_session;
    TuningSpec m_spec;
    Limits m_limits;
    std::function<double()> m_clock;
    RunnerStates* m_states; // a child
    Done m_done;
    Run m_run;
};

} // namespace opentop
