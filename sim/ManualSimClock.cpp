#include "sim/ManualSimClock.h"

namespace opentop {

ManualSimClock::ManualSimClock(qint64 startMs)
    : m_now(startMs)
{
}

qint64 ManualSimClock::nowMs() const
{
    return m_now.load();
}

void ManualSimClock::setNowMs(qint64 ms)
{
    m_now.store(ms);
}

void ManualSimClock::advanceMs(qint64 ms)
{
    m_now.fetch_add(ms);
}

} // namespace opentop
