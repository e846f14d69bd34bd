#include "sim/DcSpeedLoop.h"

#include <algorithm>

namespace opentop {

void DcSpeedLoop::reset()
{
    *this = DcSpeedLoop();
}

double DcSpeedLoop::step(double command, double feedback, const Gains& g)
{
    const double e = command - feedback;
    if (!m_started) {
        m_dReference = e;
        m_started = true;
    }
    const int period = std::max(1, g.dPeriodMs);
    if (++m_dCount >= period) {
        m_dTerm = g.d * (e - m_dReference);
        m_dReference = e;
        m_dCount = 0;
    }
    const double unsaturated = g.p * e + g.i * (m_sum + e) + m_dTerm;
    const double u = std::clamp(unsaturated, -kOutputFullScale, kOutputFullScale);
    // Conditional integration: the sum grows only while it does not push further into the limit.
    if (u == unsaturated || (unsaturated > 0) != (e > 0))
        m_sum += e;
    return u / kOutputFullScale;
}

} // namespace opentop
