#pragma once

#include "sim/SimClock.h"

#include <QElapsedTimer>

namespace opentop {

// Monotonic wall time since construction.
class SteadySimClock : public SimClock
{
public:
    SteadySimClock();
    qint64 nowMs() const override;

private:
    QElapsedTimer m_timer;
};

} // namespace opentop
