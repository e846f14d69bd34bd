#pragma once

#include "model/eol/LimitCheck.h"
#include "model/eol/RecipeTypes.h"
#include "model/eol/UnitRecord.h"
#include "model/run/RunnerStates.h"

#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QPointer>
#include <functional>
#include <optional>

namespace opentop {

class DeviceSession;
struct ParamValue;

// The measuring steps of a recipe on one drive (docs/recipe-format.md, "Steps"): wait for
// speed, hold, no alarm, read, and the time a stop took. Each reads the drive, records what it
// measured and judges it against the step's limits (LimitCheck). Live values are polled in a loop
// of the runner's current state (RunnerStates::every), so the loop ends with that state; an alarm
// seen in them ends the step, named from the drive's newest alarm record. EolStepRunner moves the
// motor and decides what follows each step.
class StepMeasure : public QObject
{
    Q_OBJECT
public:
    // The step's verdict: empty when it passed, else the failure in words (names the step).
    using Done = std::function<void(const QString& failure)>;

    StepMeasure(DeviceSession* session, RunnerStates& states, int pollMs, int maxFailedPolls,
                QObject* parent = nullptr);

    // The step that records and failures name from now on ("step 4 (wait for speed)").
    void setStep(const QString& text) { m_step = text; }

    void waitSpeed(const RecipeStep& step, Done done);
    void hold(const RecipeStep& step, Done done);
    void noAlarm(Done done);
    void read(const RecipeStep& step, Done done);
    // The time the stop step allows, `then` given it in seconds: its deceleration, else the
    // knob's maximum of running data `selected` (1–8; 0: none selected), else that running
    // data's deceleration setting, else `unknownS`; plus the step's margin.
    void stopAllowance(const RecipeStep& step, int selected, double unknownS,
                       std::function<void(double limitS)> then);
    // The stop step's verdict (as Done's) on a stop that took `ms`, and its record.
    QString stopTime(bool confirmed, const QString& detail, qint64 ms, double limitS);

    // An answer for the current state of `states`: dropped once that state has ended (guard)
    // or the states are gone with their runner while the session lives on. RunnerStates::guard
    // could do the second part itself.
    template <class F> static auto answer(RunnerStates& states, F f)
    {
        return [alive = QPointer<RunnerStates>(&states),
                g = states.guard(std::move(f))](auto&&... args) {
            if (alive)
                g(std::forward<decltype(args)>(args)...);
        };
    }

signals:
    void measured(const opentop::Measurement& measurement);
    // The current speed as read during wait and hold steps.
    void speedSampled(double speed, const QString& unit);

private:
    using Values = QHash<QString, ParamValue>;
    void record(const QString& quantity, double value, const QString& unit,
                std::optional<double> lower, std::optional<double> upper, bool pass);
    // One poll of `names` (plus the alarm role's parameter): `then` gets the values by name;
    // `done` gets the failure once too many polls failed or an alarm is active.
    void poll(const QStringList& names, std::function<void(const Values&)> then, Done done);
    bool alarmIn(const Values& values) const;
    void failWithAlarm(const QString& reason, Done done);
    QString labelOf(const QString& parameter) const;
    QString recordLabelOf(const QString& parameter) const; // English: for result records
    QString unitOf(const QString& parameter) const;

    QPointer<DeviceSession> m_session;
    RunnerStates& m_states;
    int m_pollMs;
    int m_maxFailedPolls;
    QString m_step;
    bool m_alarmSeen = false;
    int m_failedPolls = 0;
    QElapsedTimer m_clock;             // since the wait or hold began
    std::optional<double> m_lastSpeed; // the wait's last speed read
    LimitCheck m_hold;                 // the hold's readings
};

} // namespace opentop
