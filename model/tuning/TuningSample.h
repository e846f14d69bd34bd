#pragma once

#include <QVector>

namespace opentop {

// One reading during a tuning test, in the registers' engineering units.
struct TuningSample
{
    double tMs = 0;     // since the test's reference moment (the step, the relay's start)
    double command = 0; // the set point in force (closed loop) or the duty sent (open loop)
    double speed = 0;   // the regulated feedback
    double current = 0; // load current
    double output = 0;  // output duty
};

using TuningSamples = QVector<TuningSample>;

} // namespace opentop
