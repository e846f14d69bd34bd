#include "DbuMotor.h"

#include <algorithm>
#include <cmath>

namespace opentop {

namespace {

constexpr double kFullScaleRpm = 3000;
constexpr double kOverloadPercent = 120;
constexpr double kWarningSpeed = 3500;
constexpr double kAlarmSpeed = 3800;

} // namespace

DbuMotor::Events DbuMotor::step(const Input& input, int dtMs)
{
    Events events;
    m_ramp.step(input.target, input.accelPerSecond, input.decelPerSecond, dtMs);
    const double speed = std::abs(m_ramp.value());
    // Load rate: friction, a speed-proportional part and the torque needed to accelerate.
    const bool moving = speed > 0 || input.commanded;
    const double rate = std::max(
        10 + 30 * speed / kFullScaleRpm + 40 * std::abs(m_ramp.rate()) / 6000, input.loadFloor);
    m_load = moving ? std::clamp(rate * input.loadScale + input.loadOffset, 0.0, 200.0) : 0;
    m_overloadMs = m_load > kOverloadPercent ? m_overloadMs + dtMs : 0;
    if (m_overloadMs > 0 && m_overloadMs >= input.overloadMs)
        events.alarm = kAlarmOverload;
    else if (speed > kAlarmSpeed)
        events.alarm = kAlarmOverSpeed;

    const bool load = m_load > input.loadWarning;
    if (load && !m_loadWarning)
        events.warnings << kWarningLoad;
    m_loadWarning = load;
    const bool fast = speed > kWarningSpeed;
    if (fast && !m_speedWarning)
        events.warnings << kWarningOverSpeed;
    m_speedWarning = fast;
    m_revolutions += speed / 60.0 * dtMs / 1000.0;
    return events;
}

void DbuMotor::stop()
{
    m_ramp.set(0);
    m_load = 0;
    m_overloadMs = 0;
}

void DbuMotor::reset()
{
    stop();
    m_loadWarning = m_speedWarning = false;
}

} // namespace opentop
