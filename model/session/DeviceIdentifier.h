#pragma once

#include "model/session/DeviceInfo.h"

#include <QObject>
#include <functional>

namespace opentop {

class ModbusClient;
class ProfileRegistry;
struct ModbusResult;

// Finds out which family, variant and firmware answers at a machine number, using each
// profile's identify read. Asynchronous: the UI thread never waits on the wire.
class DeviceIdentifier : public QObject
{
    Q_OBJECT
public:
    using Done = std::function<void(const DeviceInfo&)>;

    DeviceIdentifier(ModbusClient* client, const ProfileRegistry& registry,
                     QObject* parent = nullptr);

    // Asks `slave`; `done` runs on this object's thread when the answer is known.
    void identify(int slave, Done done, int timeoutMs = -1);
    // Decodes an identify reply for `family` (public for the command line's scan and for tests).
    DeviceInfo interpret(int slave, int profileIndex, const ModbusResult& result) const;

private:
    void tryProfile(int slave, int profileIndex, Done done, int timeoutMs);

    ModbusClient* m_client;
    const ProfileRegistry& m_registry;
};

} // namespace opentop
