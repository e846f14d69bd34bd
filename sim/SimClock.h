#pragma once

#include <QtGlobal>

namespace opentop {

// Time source of the simulator in milliseconds. Devices never read a clock themselves: the bus
// passes `now` in, so that tests drive time with a ManualSimClock.
class SimClock
{
public:
    virtual ~SimClock() = default;
    virtual qint64 nowMs() const = 0;
};

} // namespace opentop
