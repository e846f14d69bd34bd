#pragma once

#include "ConnectionSettings.h"

#include <QString>
#include <memory>

namespace opentop {

class ModbusBackend;
class ModbusClient;
class SimBus;

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
    static Made makeClient(const ConnectionSettings& settings);
};

} // namespace opentop
