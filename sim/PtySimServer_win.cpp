// PtySimServer on Windows: there are no pseudo-terminals, so opentop-sim serves Modbus TCP only
// there (--tcp) and open() says so. A virtual COM port pair (com0com) could take the pty's
// place one day; until then the serial side is simulated on Linux.
#include "sim/PtySimServer.h"

#include "sim/SimBus.h"

#include <QLockFile>

namespace opentop {

PtySimServer::PtySimServer(std::shared_ptr<SimBus> bus, const WireTiming& timing, bool wireTiming,
                           QObject* parent)
    : QObject(parent)
    , m_bus(std::move(bus))
    , m_timing(timing)
    , m_wireTiming(wireTiming)
    , m_replies(nullptr)
{
}

PtySimServer::~PtySimServer() = default;

bool PtySimServer::open(const QString& linkPath, QString* error)
{
    Q_UNUSED(linkPath);
    m_linkHolderPid = 0;
    if (error)
        *error = tr("a simulated serial line needs a pseudo-terminal, which Windows does not "
                    "have: serve Modbus TCP with --tcp PORT (e.g. --tcp 5020) and connect with "
                    "--tcp 127.0.0.1:5020");
    return false;
}

void PtySimServer::close() {}

void PtySimServer::unplug() {}

bool PtySimServer::replug(QString* error)
{
    return open(QString(), error);
}

} // namespace opentop
