#pragma once

#include "model/eol/Recipe.h"

#include <QObject>
#include <QPointer>
#include <QVector>
#include <functional>

namespace opentop {

class DeviceSession;
class ModbusClient;
class ProfileRegistry;

// Resets the alarms a unit found latched before its test (the previous unit stalled), drive by
// drive, by each drive's own reset command and rules (AlarmHistory::reset: an alarm that only a
// power cycle clears is said so, never hidden). Only the recipe's machine numbers that had the
// alarm are sent anything; the station asks the operator first.
class StationAlarmReset : public QObject
{
    Q_OBJECT
public:
    struct Result
    {
        int machineNumber = 0;
        bool cleared = false; // the drive reads back no active alarm
        QString text;         // what happened, in words (AlarmHistory's explanation)
    };
    using Done = std::function<void(const QVector<Result>& results)>;

    StationAlarmReset(ModbusClient* client, const ProfileRegistry& registry, const Recipe& recipe,
                      QObject* parent = nullptr);

    // `done` runs once, never before reset() returns.
    void reset(const QVector<int>& machineNumbers, Done done);
    static bool allCleared(const QVector<Result>& results);

private:
    void next();

    QPointer<ModbusClient> m_client;
    const ProfileRegistry& m_registry;
    Recipe m_recipe;
    QVector<int> m_left; // machine numbers still to reset
    QVector<Result> m_results;
    DeviceSession* m_session = nullptr;
    Done m_done;
};

} // namespace opentop
