#include "transport/ReplyTiming.h"

namespace opentop {

void ReplyTiming::reset()
{
    m_slow = 0;
    m_fast = 0;
}

void ReplyTiming::learn(double elapsedMs, double wireMs)
{
    if (wireMs <= 0)
        return; // Modbus TCP: transaction ids, no wire
    // Well below the wire time: no UART in the way (a late reply would have been caught by
    // the suspect check that makes an exchange unclean). In between: proves nothing.
    if (elapsedMs < 0.5 * wireMs)
        ++m_fast;
    else if (elapsedMs >= kMargin * wireMs)
        ++m_slow;
}

bool ReplyTiming::tooEarly(double elapsedMs, double wireMs) const
{
    return wireMs > 0 && keepsWireTime() && elapsedMs < kMargin * wireMs;
}

} // namespace opentop
