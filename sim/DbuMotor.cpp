#include "sim/DbuMotor.h"

#include <algorithm>
#include <cmath>

namespace opentop {

namespace {

constexpr double kFullScaleRpm = 3000;
constexpr double kOverloadPercent = 120;
constexpr double kWarningSpeed = 3500;
constexpr double kAlarmSpeed = 3800;
constexpr double kStallLoad = 150; // a stalled motor: overload alarm after alarm.overload_time
constexpr double kHeldLoad = 115;  // held below its target: at the torque limit, no overload

} // namespace

DbuMotor::Events DbuMotor::step(const Input& input, int dtMs)
{
    Events events;
    static const SimDefects kGood;
    const SimDefects& defect = input.defects ? *input.defects : kGood;
    m_runningMs = input.commanded ? m_runningMs + dtMs : 0;
    if (defect.alarmCode && input.commanded && m_runningMs >= defect.alarmAfterMs) {
        events.alarm = *defect.alarmCode; // a defect: the alarm while running
        return events;
    }
    // A defect may hold the motor below its target: it then works at its torque limit.
    const double magnitude = std::abs(input.target);
    const double reachable = defect.reachable(magnitude);
    const bool held = reachable < magnitude && std::abs(m_ramp.value()) >= reachable;
    m_ramp.step(input.target < 0 ? -reachable : reachable, input.accelPerSecond,
                input.decelPerSecond, dtMs);
    const double speed = std::abs(m_ramp.value());
    // Load rate: friction, a speed-proportional part and the torque needed to accelerate.
    const bool moving = speed > 0 || input.commanded;
    const double rate =
        std::max(10 + 30 * speed / kFullScaleRpm + 40 * std::abs(m_ramp.rate()) / 6000,
                 held ? (defect.stall ? kStallLoad : kHeldLoad) : 0.0);
    m_load = moving ? std::clamp(defect.load(rate) + input.loadOffset, 0.0, 200.0) : 0;
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
    m_runningMs = 0;
}

void DbuMotor::reset()
{
    stop();
    m_loadWarning = m_speedWarning = false;
}

} // namespace opentop
