#include "transport/LineTiming.h"

namespace opentop {

LineTiming::LineTiming()
{
    m_clock.start();
}

void LineTiming::sending()
{
    m_timer.start();
    m_sentAtMs = nowMs();
}

int LineTiming::turnaroundMs(int lineMs) const
{
    return m_turnaroundMs >= 0 ? m_turnaroundMs : lineMs;
}

double LineTiming::frameGapMs(double lineMs) const
{
    return m_frameGapMs >= 0 ? m_frameGapMs : lineMs;
}

} // namespace opentop
