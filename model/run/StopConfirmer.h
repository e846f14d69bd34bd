#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QStringList>
#include <QTimer>
#include <functional>
#include <optional>

namespace opentop {

class DeviceSession;

// What became of one drive after a stop.
struct StopResult
{
    enum class State
    {
        Stopped,
        StillRunning,
        NoAnswer
    };
    int slave = 0;
    State state = State::NoAnswer;
    QString family;
    std::optional<double> speed; // last speed read, in the currentSpeed role's unit
    QString speedText;           // "0 r/min"
    qint64 elapsedMs = 0;        // since the stop was sent
    QString detail;              // why it did not stop or answer, for people
};

// Confirms that one drive stops after a stop command by polling its "running" role (or its
// current speed) until it has stopped. The deadline follows the drive's deceleration settings
// (the "decelerations" role) and, while running data with a knob runs, the knob's maximum (the
// profile's decelerationKnobs: the DBU's SD knob for SPno1, not readable), within fixed bounds;
// past it, a drive that is still slowing down gets more time up to the bound, one whose speed
// no longer falls is reported as still running. A drive whose speed has not fallen at all since
// the stop is judged by the settings' deadline alone: the knob's time is for a drive that slows.
class StopConfirmer : public QObject
{
    Q_OBJECT
public:
    struct Timing
    {
        int pollMs = 100;
        int stallMs = 1000;        // no fall in speed for this long past the deadline: running
        int marginMs = 1000;       // added to the deceleration time
        double decelFactor = 1.2;  // deceleration settings are for a full-speed stop
        int unknownDecelMs = 5000; // when the profile has no deceleration settings
        int maxMs = 35000;         // hard bound after the stop was sent
        int maxFailedReads = 3;    // consecutive failed reads before "no answer"
    };

    // `sinceStop` runs from the moment the stop was sent.
    StopConfirmer(DeviceSession* session, const QElapsedTimer& sinceStop, const Timing& timing,
                  QObject* parent = nullptr);

    void start(std::function<void(const StopResult&)> done);
    // The deadline derived from the settings read (valid after the first read).
    qint64 expectedMs() const { return m_expectedMs; }

private:
    void round();
    void evaluate(bool readOk, std::optional<bool> running, std::optional<double> speed,
                  const QString& speedText, const QString& error);
    void finish(StopResult::State state, const QString& detail);
    QStringList decelParameters() const;
    // The profile's decelerationKnobs: the knob's maximum when the running data selected has
    // one (or when which one runs is not known), nothing otherwise.
    std::optional<double>
    knobSeconds(const std::function<std::optional<double>(const QString&)>& raw) const;

    DeviceSession* m_session;
    QElapsedTimer m_sinceStop;
    Timing m_timing;
    QTimer m_timer;
    std::function<void(const StopResult&)> m_done;
    bool m_first = true;
    qint64 m_expectedMs = 0;
    qint64 m_settingsMs = 0; // the deadline of the readable settings alone (no knob)
    bool m_fell = false;     // the speed has fallen since the first read
    int m_failures = 0;
    std::optional<double> m_lowest; // lowest speed seen so far
    qint64 m_progressMs = 0;        // when the speed last fell
    StopResult m_result;
    QString m_priorityNote; // the drive does not take bus commands (motionPriority)
};

} // namespace opentop
