#pragma once

#include "sim/WireTiming.h"
#include "transport/ModbusBackend.h"

#include <QCoreApplication>
#include <memory>

namespace opentop {

class SimBus;

// The in-process simulated bus behind `--sim SPEC`: requests are encoded as RTU frames, handled
// by the SimBus and the replies decoded, exactly as they would be on a line, and both directions
// go to the traffic log. Lost replies cost the request's timeout; wire timing optionally adds
// the transmission times at `baud`.
class SimBackend : public ModbusBackend
{
    Q_DECLARE_TR_FUNCTIONS(opentop::SimBackend)
public:
    explicit SimBackend(std::shared_ptr<SimBus> bus, bool wireTiming = false, int baud = 19200);
    ~SimBackend() override;

    bool open(QString* error) override;
    void close() override;
    bool isOpen() const override { return m_open; }
    ModbusResult transact(const ModbusRequest& request, int timeoutMs) override;
    QString describe() const override;

    SimBus& bus() const { return *m_bus; }
    // The port's format (the connection's settings): a request without one of its own goes
    // out in it, and the bus's devices hear it or not as on a line.
    void setPortLine(const LineFormat& format) { m_port = format; }

private:
    std::shared_ptr<SimBus> m_bus;
    bool m_wireTiming;
    WireTiming m_timing;
    LineFormat m_port;
    bool m_open = false;
};

} // namespace opentop
