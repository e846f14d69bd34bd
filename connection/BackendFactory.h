#pragma once

#include "transport/ConnectionSettings.h"

#include <QString>
#include <memory>

namespace opentop {

class ModbusBackend;
class ModbusClient;
class SimBus;
class TrafficLog;

// Makes the backend a ConnectionSettings names: libmodbus RTU, libmodbus TCP, or the
// in-process simulated bus.
class BackendFactory
{
public:
    struct Made
    {
        std::unique_ptr<ModbusClient> client;
        std::shared_ptr<SimBus> simBus; // set for a simulated bus (tests and the sim console)
        QString error;
    };
    // `log`, when given, records every frame of the connection (it must outlive the client).
    static Made makeClient(const ConnectionSettings& settings, TrafficLog* log = nullptr);
};

} // namespace opentop
