#pragma once

#include "model/run/StopAll.h"

#include <QObject>
#include <QPair>
#include <QVector>
#include <functional>
#include <memory>
#include <optional>

namespace opentop {

class DeviceSession;
class ModbusClient;
class Profile;
class ProfileRegistry;
struct ParameterMeta;

// Test runs by role: start, stop, direction, running data selection, hold/free, coast and
// speed set points, each sent only when asked for and only to a drive that takes motion
// commands over the bus (the "motionPriority" role); and stop-all (StopAll), a broadcast of
// every family's "stop" role followed by a confirmation that each known drive has stopped.
class RunControl : public QObject
{
    Q_OBJECT
public:
    enum class Action
    {
        Start,
        Stop,
        Cw,
        Ccw,
        Select,
        Hold,
        Free,
        Coast,
        Speed
    };
    struct Command
    {
        Action action = Action::Stop;
        int select = 0; // Select: running data number N (1-based)
        QString speed;  // Speed: the set point as typed ("50", "50 %", "-20")
    };
    // "start", "select 3", "speed -50"; nothing and *error for anything else.
    static std::optional<Command> parse(const QStringList& words, QString* error);
    static QString actionName(Action action);
    static QString roleOf(Action action);
    // The actions a profile has roles for ("start", "stop", ..., "select N", "speed VALUE").
    static QStringList actionsOf(const Profile& profile);

    enum class Failure
    {
        None,
        Unsupported,  // the drive has no such command
        InvalidValue, // refused before sending (select number, speed value)
        Priority,     // the drive does not take motion commands over the bus; nothing sent
        Communication,
        Mismatch // read back differently
    };
    struct Plan
    {
        Failure failure = Failure::None;
        QString error;
        const ParameterMeta* meta = nullptr;
        QString text;        // what DeviceSession::write gets
        QString description; // "run.start = START (1) (0x2003, function 06)"
    };
    struct Outcome
    {
        bool ok = false;
        bool sent = false;
        Failure failure = Failure::None;
        QString error;
        QString deviceError;
        QString explanation; // why and what to do (priority, active alarm)
        Plan plan;
    };
    using Done = std::function<void(const Outcome&)>;

    // The drive's state after a command: every field of the "running" role's parameter, the
    // current and target speed and the running data selection, as label/text pairs.
    struct State
    {
        bool ok = false;
        QString error;
        std::optional<bool> running;
        QVector<QPair<QString, QString>> items;
    };

    using Broadcast = StopBroadcast;
    using StopReport = opentop::StopReport;

    RunControl(ModbusClient* client, const ProfileRegistry& registry, QObject* parent = nullptr);

    static Plan plan(const DeviceSession& session, const Command& command);
    void execute(DeviceSession* session, const Command& command, Done done);
    // `settleMs`: wait this long first, so that a drive's status reflects a command just sent.
    void readState(DeviceSession* session, std::function<void(const State&)> done,
                   int settleMs = 0);

    static QVector<Broadcast> broadcastPlan(const ProfileRegistry& registry);
    // Existing sessions to use for known drives (others are identified after the broadcast).
    void setSessionLookup(std::function<DeviceSession*(int slave)> lookup)
    {
        m_lookup = std::move(lookup);
    }
    void setStopTiming(const StopConfirmer::Timing& timing) { m_timing = timing; }
    void stopAll(const QVector<int>& knownSlaves, std::function<void(const StopReport&)> done);

private:
    void sendCommand(DeviceSession* session, const Plan& plan, Done done);
    void explainRefusal(DeviceSession* session, Outcome outcome, Done done);

    ModbusClient* m_client;
    const ProfileRegistry& m_registry;
    std::function<DeviceSession*(int)> m_lookup;
    StopConfirmer::Timing m_timing;
};

} // namespace opentop
