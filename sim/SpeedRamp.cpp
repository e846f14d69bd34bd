#include "sim/SpeedRamp.h"

#include <cmath>

namespace opentop {

void SpeedRamp::set(double value)
{
    m_value = value;
    m_rate = 0;
}

void SpeedRamp::step(double target, double upPerSecond, double downPerSecond, int dtMs)
{
    if (dtMs <= 0)
        return;
    const double before = m_value;
    const bool speedingUp = std::abs(target) > std::abs(m_value) && target * m_value >= 0;
    const double maxStep = (speedingUp ? upPerSecond : downPerSecond) * dtMs / 1000.0;
    const double diff = target - m_value;
    if (std::abs(diff) <= maxStep)
        m_value = target;
    else
        m_value += diff > 0 ? maxStep : -maxStep;
    m_rate = (m_value - before) * 1000.0 / dtMs;
}

} // namespace opentop
