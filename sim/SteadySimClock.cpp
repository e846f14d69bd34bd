#include "sim/SteadySimClock.h"

namespace opentop {

SteadySimClock::SteadySimClock()
{
    m_timer.start();
}

qint64 SteadySimClock::nowMs() const
{
    return m_timer.elapsed();
}

} // namespace opentop
