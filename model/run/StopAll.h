#pragma once

#include "model/run/StopConfirmer.h"

#include <QObject>
#include <QVector>
#include <functional>
#include <memory>

namespace opentop {

class DeviceIdentifier;
class DeviceSession;
class ModbusClient;
class ProfileRegistry;
struct ParameterMeta;

// A broadcast of one family's "stop" role.
struct StopBroadcast
{
    QString family;
    const ParameterMeta* meta = nullptr;
    qint64 raw = 0;
    QString description; // "run.start = STOP (0) (0x2003, function 06)"
    bool sent = false;
    QString error;
};

struct StopReport
{
    QVector<StopBroadcast> broadcasts;
    QVector<StopResult> drives; // in the order of the known machine numbers
    bool broadcastOk() const;
    bool allStopped() const;
    bool anyStillRunning() const;
    bool anyNoAnswer() const;
};

// Stop-all: first every family's stop command as a broadcast (machine number 0; nobody
// answers, so nothing is waited for), then each known drive is identified and watched until it
// has stopped (StopConfirmer), all at the same time. Writing another family's stop register is
// harmless: a drive without it refuses the broadcast silently (a DBU notes E0h in 0x007B).
class StopAll : public QObject
{
    Q_OBJECT
public:
    using Done = std::function<void(const StopReport&)>;

    StopAll(ModbusClient* client, const ProfileRegistry& registry, QObject* parent = nullptr);

    // The broadcasts, one per family that has a stop role and takes broadcasts.
    static QVector<StopBroadcast> plan(const ProfileRegistry& registry);
    // Existing sessions to use for known drives (others are identified after the broadcast).
    void setSessionLookup(std::function<DeviceSession*(int slave)> lookup)
    {
        m_lookup = std::move(lookup);
    }
    void setTiming(const StopConfirmer::Timing& timing) { m_timing = timing; }
    void run(const QVector<int>& knownSlaves, Done done);

private:
    struct Run;
    void broadcastNext(std::shared_ptr<Run> run);
    void confirmNext(std::shared_ptr<Run> run);
    void confirm(std::shared_ptr<Run> run, int index, DeviceSession* session);
    void finishIfDone(const std::shared_ptr<Run>& run);

    ModbusClient* m_client;
    const ProfileRegistry& m_registry;
    std::function<DeviceSession*(int)> m_lookup;
    StopConfirmer::Timing m_timing;
};

} // namespace opentop
