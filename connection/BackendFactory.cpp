#include "connection/BackendFactory.h"

#include "sim/SimBackend.h"
#include "sim/SimBus.h"
#include "transport/ModbusClient.h"
#include "transport/RtuBackend.h"
#include "transport/TcpBackend.h"

namespace opentop {

BackendFactory::Made BackendFactory::makeClient(const ConnectionSettings& settings, TrafficLog* log)
{
    Made made;
    made.error = settings.validate();
    if (!made.error.isEmpty())
        return made;
    std::unique_ptr<ModbusBackend> backend;
    switch (settings.kind) {
    case ConnectionSettings::Kind::Serial:
        backend = std::make_unique<RtuBackend>(settings);
        break;
    case ConnectionSettings::Kind::Tcp:
        backend = std::make_unique<TcpBackend>(settings);
        break;
    case ConnectionSettings::Kind::Simulated: {
        made.simBus = SimBus::fromSpec(settings.simSpec, &made.error);
        if (!made.simBus)
            return made;
        auto sim = std::make_unique<SimBackend>(made.simBus, false, settings.baud);
        sim->setPortLine(settings.line());
        backend = std::move(sim);
        break;
    }
    }
    backend->setTrafficLog(log);
    made.client = std::make_unique<ModbusClient>(std::move(backend), settings);
    return made;
}

} // namespace opentop
