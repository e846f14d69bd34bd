#pragma once

#include "model/eol/RecipeTypes.h"
#include "model/eol/UnitRecord.h"
#include "model/run/StopConfirmer.h"

#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QPointer>
#include <functional>
#include <optional>

namespace opentop {

class DeviceSession;
class RunControl;
struct ParamValue;
struct ParameterMeta;

// Runs one drive's recipe steps (docs/recipe-format.md, "Steps"): priority, running data,
// speed command, start, wait for speed, hold while measuring, no alarm, stop, read. Motion
// happens only in these steps. Each measured value is compared with its limits as it is
// taken; the first failure, an alarm while running or abort() stops the motor at once and
// confirms it stopped (StopConfirmer). Communication priority taken by a priority step is given
// back, as the drive held it, once the motor has stopped.
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
    // `done` runs once, never before start() returns.
    void start(Done done);
    // Ends the steps with `reason`: the motor is stopped and the stop confirmed first when
    // motion may have begun.
    void abort(const QString& reason);
    bool isRunning() const { return bool(m_done); }

signals:
    void stepStarted(int index, const QString& title);
    void measured(const opentop::Measurement& measurement);
    // The current speed as read during wait and hold steps.
    void speedSampled(double speed, const QString& unit);

private:
    struct Stats
    {
        double min = 0, max = 0, sum = 0;
        int count = 0;
        void add(double v);
    };

    void next();
    void runCommand(int action, int select, const QString& speed, std::function<void()> then);
    void runPriority();
    void runWaitSpeed(const RecipeStep& step);
    void runHold(const RecipeStep& step);
    void runNoAlarm();
    void runStop(const RecipeStep& step);
    void runRead(const RecipeStep& step);
    // One poll of `names` (plus the alarm role's parameter); `then` gets the values by name,
    // or the poll loop ends in a failure once too many polls failed.
    void poll(const QStringList& names,
              std::function<void(const QHash<QString, ParamValue>&)> then);
    bool alarmIn(const QHash<QString, ParamValue>& values) const;
    void failWithAlarm(const QString& reason);
    void record(const QString& quantity, double value, const QString& unit,
                std::optional<double> lower, std::optional<double> upper, bool pass);
    void fail(const QString& reason);
    void stopMotor(std::function<void(bool confirmed, const QString& detail, qint64 ms)> then,
                   int marginMs = -1);
    void givePriorityBack(std::function<void()> then);
    void finish(bool ok);
    QString stepText() const;
    QString labelOf(const QString& parameter) const;
    QString recordLabelOf(const QString& parameter) const; // English: for result records
    QString unitOf(const QString& parameter) const;
    bool current(quint64 token) const { return token == m_token; }

    QPointer<DeviceSession> m_session;
    RunControl* m_run;
    QVector<RecipeStep> m_steps;
    Timing m_timing;
    Done m_done;
    Result m_result;
    int m_index = -1;
    quint64 m_token = 0;   // bumped when the steps end, so late answers are ignored
    bool m_motion = false; // a command that may run the motor was sent
    bool m_stopped = true;
    int m_selected = 0;                      // running data selected by a select step
    std::optional<QString> m_priorityBefore; // the priority setting before the priority step
    bool m_alarmSeen = false;
    int m_failedPolls = 0;
};

} // namespace opentop
