#include "sim/SimBackend.h"

#include "sim/SimBus.h"
#include "sim/SimLog.h"
#include "transport/RtuFrame.h"

#include <QElapsedTimer>

namespace opentop {

SimBackend::SimBackend(std::shared_ptr<SimBus> bus, bool wireTiming, int baud)
    : m_bus(std::move(bus))
    , m_wireTiming(wireTiming)
    , m_timing(baud, 'N')
{
}

SimBackend::~SimBackend() = default;

bool SimBackend::open(QString* error)
{
    if (!m_bus) {
        if (error)
            *error = tr("no simulated bus");
        return false;
    }
    m_open = true;
    return true;
}

void SimBackend::close()
{
    m_open = false;
}

QString SimBackend::describe() const
{
    return QStringLiteral("sim %1").arg(m_bus ? m_bus->spec() : QString());
}

ModbusResult SimBackend::transact(const ModbusRequest& request, int timeoutMs)
{
    ModbusResult result;
    result.attempts = 1;
    if (!m_open) {
        result.error = ModbusError::NotConnected;
        result.message = tr("the simulated bus is not open");
        return result;
    }
    if (m_bus->isUnplugged()) {
        m_open = false;
        result.error = ModbusError::PortError;
        result.message = tr("the simulated adapter was unplugged");
        return result;
    }
    const int timeout =
        timeoutMs > 0 ? timeoutMs : (request.timeoutMs > 0 ? request.timeoutMs : 200);
    QElapsedTimer timer;
    timer.start();
    auto elapsed = [&timer] { return double(timer.nsecsElapsed()) / 1e6; };
    const QByteArray adu = RtuFrame::encodeRequest(request);
    const LineFormat line = request.line.isSet() ? request.line : m_port;
    logFrame(true, adu, request,
             line == m_port ? request.describe()
                            : QStringLiteral("%1 [%2]").arg(request.describe(), line.text()),
             QString());
    const WireTiming timing = m_timing.at(line);
    const SimOutcome outcome = m_bus->handleFrame(adu, m_bus->nowMs(), line);

    if (request.isBroadcast()) {
        if (m_wireTiming && !sleepInterruptible(timing.broadcastDelayMs(int(adu.size())))) {
            result.error = ModbusError::Cancelled;
            return result;
        }
        result.error = ModbusError::Ok;
        result.elapsedMs = elapsed();
        return result;
    }
    double delay = outcome.delayMs;
    if (m_wireTiming && !outcome.reply.isEmpty())
        delay += timing.replyDelayMs(int(adu.size()), int(outcome.reply.size()));
    const bool lost = outcome.reply.isEmpty() || delay >= timeout;
    if (!sleepInterruptible((lost ? timeout : delay) - elapsed())) {
        result.error = ModbusError::Cancelled;
        result.message = tr("interrupted while waiting");
        result.elapsedMs = elapsed();
        return result;
    }
    result.elapsedMs = elapsed();
    if (lost) {
        result.error = ModbusError::Timeout;
        result.message = tr("no reply within %1 ms").arg(timeout);
        logEvent(request, result.message, result.errorText());
        return result;
    }
    RtuFrame::decodeReply(request, outcome.reply, &result);
    result.attempts = 1;
    result.reply = outcome.reply;
    result.elapsedMs = elapsed();
    logReply(outcome.reply, quint8(outcome.reply.at(0)),
             outcome.reply.size() > 1 ? quint8(outcome.reply.at(1)) : -1, request, result);
    return result;
}

} // namespace opentop
