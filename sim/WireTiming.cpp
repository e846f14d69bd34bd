#include "sim/WireTiming.h"

namespace opentop {

WireTiming::WireTiming(int baud, char parity, double turnaroundMs, int stopBits)
    : m_baud(baud > 0 ? baud : 19200)
    , m_parity(parity)
    , m_turnaroundMs(turnaroundMs)
    , m_stopBits(stopBits == 2 ? 2 : 1)
{
}

WireTiming WireTiming::at(const LineFormat& format) const
{
    if (!format.isSet())
        return *this;
    return WireTiming(format.baud, format.parity, m_turnaroundMs, format.stopBits);
}

int WireTiming::bitsPerChar() const
{
    return 9 + (m_parity == 'E' || m_parity == 'O' ? 1 : 0) + m_stopBits;
}

double WireTiming::charMs() const
{
    return bitsPerChar() * 1000.0 / m_baud;
}

double WireTiming::frameMs(int bytes) const
{
    return bytes * charMs();
}

double WireTiming::gapMs() const
{
    return m_baud > 19200 ? 1.75 : 3.5 * charMs();
}

double WireTiming::replyDelayMs(int requestBytes, int replyBytes, double turnaroundMs) const
{
    const double turnaround = turnaroundMs >= 0 ? turnaroundMs : m_turnaroundMs;
    return frameMs(requestBytes) + gapMs() + turnaround + frameMs(replyBytes);
}

double WireTiming::broadcastDelayMs(int requestBytes) const
{
    return frameMs(requestBytes) + gapMs() + m_turnaroundMs;
}

} // namespace opentop
