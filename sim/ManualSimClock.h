#pragma once

#include "sim/SimClock.h"

#include <atomic>

namespace opentop {

// A clock that only moves when told to (tests).
class ManualSimClock : public SimClock
{
public:
    explicit ManualSimClock(qint64 startMs = 0);
    qint64 nowMs() const override;
    void setNowMs(qint64 ms);
    void advanceMs(qint64 ms);

private:
    std::atomic<qint64> m_now;
};

} // namespace opentop
