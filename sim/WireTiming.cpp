#include "WireTiming.h"

namespace opentop {

WireTiming::WireTiming(int baud, char parity, double turnaroundMs)
    : m_baud(baud > 0 ? baud : 19200)
    , m_parity(parity)
    , m_turnaroundMs(turnaroundMs)
{
}

int WireTiming::bitsPerChar() const
{
    return m_parity == 'E' || m_parity == 'O' ? 11 : 10;
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
