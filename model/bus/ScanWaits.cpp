#include "model/bus/ScanWaits.h"

#include "transport/ModbusClient.h"

#include <algorithm>
#include <cmath>

namespace opentop {

namespace {

constexpr int kReadRequestBytes = 8; // id, function, address, count, CRC
constexpr double kMarginMs = 2.0;    // scheduling on the master's side
// A TCP gateway queues the request and forwards it on its own serial line.
constexpr double kGatewayMs = 50.0;

} // namespace

int ScanWaits::defaultWaitMs(const ConnectionSettings& settings, int adapterLatencyMs)
{
    const double c = settings.charTimeMs();
    const double gap = settings.baud > 19200 ? 1.75 : 3.5 * c; // Modbus RTU's, as the drive keeps
    double ms = kReadRequestBytes * c + gap + kAnswerBudgetMs + kMarginMs + adapterLatencyMs;
    if (settings.kind == ConnectionSettings::Kind::Tcp)
        ms += kGatewayMs;
    return std::clamp(int(std::ceil(ms)), kMinWaitMs, kMaxWaitMs);
}

int ScanWaits::wholeReplyWaitMs(const ConnectionSettings& settings, int firstByteWaitMs,
                                int replyBytes)
{
    const double ms = firstByteWaitMs + replyBytes * settings.charTimeMs() + kMarginMs;
    return std::clamp(int(std::ceil(ms)), kMinWaitMs, kMaxWaitMs);
}

void ScanWaits::setWaitMs(int ms)
{
    m_waitMs = ms > 0 ? std::clamp(ms, kMinWaitMs, kMaxWaitMs) : 0;
}

int ScanWaits::waitFor(int slave) const
{
    return m_waitMs > 0 ? m_waitMs
                        : defaultWaitMs(settingsFor(slave), m_client->adapterLatencyMs());
}

ConnectionSettings ScanWaits::settingsFor(int slave) const
{
    ConnectionSettings settings = m_client->settings();
    if (m_line.isSet())
        settings.setLine(m_line);
    else if (slave > 0)
        settings.setLine(m_client->driveLine(slave));
    return settings;
}

int ScanWaits::timeoutMs(int slave, int registers, Asking asking) const
{
    // A drive of its own format is asked at its rate: the waits follow it.
    const int wait = std::max(m_passWaitMs, waitFor(slave));
    const int whole = wholeReplyWaitMs(settingsFor(slave), wait, 5 + 2 * registers);
    switch (asking) {
    case Asking::Again: // four waits, or the connection's timeout
        return std::clamp(std::max({4 * wait, m_client->settings().timeoutMs, whole}), kMinWaitMs,
                          kMaxWaitMs);
    case Asking::LastOfPass: // four waits
        return std::clamp(std::max(4 * wait, whole), kMinWaitMs, kMaxWaitMs);
    case Asking::Present: // the whole reply, which may be longer than the first byte's wait
        return whole;
    case Asking::First:
        break;
    }
    return wait; // empty addresses cost this wait only
}

} // namespace opentop
