#pragma once

#include "model/profile/CodeTable.h"
#include "model/profile/ParamValue.h"
#include "model/profile/SpeedDisplay.h"

#include <QDateTime>
#include <QElapsedTimer>
#include <QMetaType>
#include <QObject>
#include <QSet>
#include <QTimer>
#include <QVector>
#include <functional>
#include <optional>

namespace opentop {

class DeviceSession;
struct ParameterMeta;
struct ModbusResult;

// One decoded value of a sample.
struct MonitorValue
{
    const ParameterMeta* meta = nullptr;
    ParamValue value;
    QString text; // formatted with its unit ("1500 r/min", "CCW", "0x0902" for bits)
};

// What one poll of a drive found.
struct MonitorSample
{
    int slave = 0;
    QDateTime timestamp;          // when the poll started
    QVector<MonitorValue> values; // in the order of the profile's "monitor" role
    std::optional<bool> running;  // the "running" role, when the profile has it
    std::optional<bool> alarmActive;
    std::optional<bool> reverse; // the "reverse" role: the motor turns CCW
    // While an alarm is active: the newest alarm record, decoded by the "alarm" code table.
    std::optional<qint64> activeAlarmCode;
    std::optional<CodeEntry> activeAlarm;
    // Current and target speed as the drive's display shows them (when it has a speed display).
    std::optional<SpeedDisplay::Shown> currentShown;
    std::optional<SpeedDisplay::Shown> targetShown;

    const MonitorValue* find(const QString& parameter) const;
    // The raw value of `parameter` when it was read (for RoleEvaluator and RunningData).
    std::optional<double> rawOf(const QString& parameter) const;
    // A speed parameter's value made signed: negative when the "reverse" role holds, for
    // registers that hold the magnitude only.
    std::optional<double> signedSpeed(const QString& parameter) const;
    // The value as text with its unit, signed like signedSpeed(): "-900 r/min"; empty when
    // not read.
    QString signedText(const QString& parameter) const;
    // "Running CW", "Running CCW", "Stopped"; empty when the family reports no running state.
    QString stateText() const;
};

// Polls a drive's "monitor" role parameters at an interval, in as few requests as the drive
// allows and at Poll priority, so that anything a user asks for goes first. A poll starts only
// when the previous one is complete; the interval is measured from start to start.
class DeviceMonitor : public QObject
{
    Q_OBJECT
public:
    explicit DeviceMonitor(DeviceSession* session, QObject* parent = nullptr);
    ~DeviceMonitor() override;

    DeviceSession* session() const { return m_session; }
    // The parameters polled: the "monitor" role, plus the "running" and "alarmActive" roles'
    // parameters when the list lacks them.
    QStringList parameters() const { return m_names; }
    // A new interval counts from the start of the poll under way or last made.
    void setInterval(int ms);
    int interval() const { return m_intervalMs; }

    // Reads the speed display settings (when the profile has them) so that samples carry
    // display values; `done` gets an error text, empty on success or when there is no display.
    void prepare(std::function<void(const QString& error)> done);
    const std::optional<SpeedDisplay>& speedDisplay() const { return m_display; }

    void start();
    void stop();
    bool isActive() const { return m_active; }

signals:
    void sample(const QDateTime& timestamp, const opentop::MonitorSample& values);
    void error(const QString& text);

private:
    struct Poll;
    void poll();
    void pollDone(const std::shared_ptr<Poll>& poll);
    void readActiveAlarm(const std::shared_ptr<Poll>& poll);
    void finish(const std::shared_ptr<Poll>& poll);
    void scheduleNext();
    MonitorSample buildSample(const Poll& poll) const;

    DeviceSession* m_session;
    QStringList m_names;
    int m_intervalMs = 500;
    bool m_active = false;
    bool m_busy = false;
    quint64 m_generation = 0; // polls of an earlier start() are ignored
    QTimer m_timer;
    QElapsedTimer m_pollClock;
    std::optional<SpeedDisplay> m_display;
    std::optional<qint64> m_activeAlarmCode; // kept while the alarm stays active
};

} // namespace opentop

Q_DECLARE_METATYPE(opentop::MonitorSample)
