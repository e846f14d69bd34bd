#pragma once

#include "model/eol/Recipe.h"
#include "model/eol/StationAlarmReset.h"

#include <QObject>
#include <QPointer>
#include <QStringList>
#include <QVector>
#include <functional>

namespace opentop {

class ModbusClient;
class ProfileRegistry;

// The alarms the last unit found latched before its test (EolRun::latchedAlarms: a station
// error, nothing was written; the unit before it stalled), and their reset when the operator
// asks for it (StationAlarmReset: each drive's own rules, one that needs a power cycle says so).
// Once every one is cleared, the station tests the same unit again.
class LatchedAlarms : public QObject
{
    Q_OBJECT
public:
    explicit LatchedAlarms(const ProfileRegistry& registry, QObject* parent = nullptr);

    void set(const QVector<int>& machineNumbers) { m_latched = machineNumbers; }
    const QVector<int>& machineNumbers() const { return m_latched; }
    bool isResetting() const { return bool(m_reset); }
    // Resets them on `recipe`'s drives, unless none is latched or a reset is under way;
    // `cleared` runs once every one is (after resetFinished()).
    void reset(ModbusClient* client, const Recipe& recipe, std::function<void()> cleared);

signals:
    void resetStarted(const QVector<int>& machineNumbers);
    void resetFinished(bool cleared, const QStringList& texts);

private:
    const ProfileRegistry& m_registry;
    QVector<int> m_latched;
    QPointer<StationAlarmReset> m_reset;
};

} // namespace opentop
