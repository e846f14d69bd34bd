#pragma once

#include "model/eol/Recipe.h"
#include "model/run/StopConfirmer.h"

#include <QCoreApplication>
#include <QObject>
#include <QPointer>
#include <QVector>
#include <functional>
#include <optional>

namespace opentop {

class DeviceSession;
class ModbusClient;
class ProfileRegistry;

// What a station found at one of its recipe's positions, and what it did.
struct PositionSafety
{
    int machineNumber = 0;
    QString name;                // "drive 1 (left conveyor)"
    bool answered = false;       // the drive answered at all
    std::optional<bool> running; // before anything was sent
    QString speedText;           // its speed then, with its unit
    bool busPriority = false;    // it took motion commands over the bus (communication priority)
    bool stopSent = false;
    bool stopConfirmed = false; // not running, or stopped and confirmed
    bool priorityGivenBack = false;
    QString problem;         // what is not safe, in words; empty when safe
    QString summary() const; // one line for the operator
    bool safe() const { return answered && stopConfirmed && problem.isEmpty(); }
    // Whether a unit may not start because of this position: a motor left turning in
    // communication priority, or one stopped but left in bus control with a problem. No answer
    // is no unit in the fixture yet, and a drive running from its inputs is the machine's.
    bool blocksUnits() const;
    // Whether the operator is told about it: a motor found turning, or a problem.
    bool worthSaying() const { return running.value_or(false) || (answered && !problem.isEmpty()); }
    // The positions that block a unit, one summary each; empty: a unit may start. The one rule
    // of the operator screen and `eol run`.
    static QString blockingText(const QVector<PositionSafety>& found);
};

// Puts a station's recipe positions in a safe state before its first unit, and whenever a unit
// ended in a way that may have left a motor turning (docs/eol-results.md, "A station that was
// killed"): each position is read (running, speed, priority); one left running in
// communication priority (a station killed mid-test) is sent its own stop, not a broadcast (a
// broadcast would reach drives that are not the station's), and watched until it has stopped;
// then control goes back to its inputs (the "ioPriority" role), unless the recipe's settings
// give the priority themselves. A drive running from its inputs (I/O priority) is not the
// station's to stop: reported. Asynchronous; `done` once, never inside run().
class StationSafeState : public QObject
{
    Q_OBJECT
public:
    using Done = std::function<void(const QVector<PositionSafety>& positions)>;

    StationSafeState(ModbusClient* client, const ProfileRegistry& registry, const Recipe& recipe,
                     QObject* parent = nullptr);
    void setStopTiming(const StopConfirmer::Timing& timing) { m_timing = timing; }
    void run(Done done);

private:
    void next();
    void read(DeviceSession* session);
    void stop(PositionSafety* found, DeviceSession* session);
    void giveBack(PositionSafety* found, DeviceSession* session);
    void finishPosition();
    bool recipeSetsPriority(const RecipePosition& position, const DeviceSession& session) const;

    ModbusClient* m_client;
    const ProfileRegistry& m_registry;
    Recipe m_recipe;
    StopConfirmer::Timing m_timing;
    Done m_done;
    int m_index = -1;
    QVector<PositionSafety> m_found;
    DeviceSession* m_session = nullptr;
};

} // namespace opentop
