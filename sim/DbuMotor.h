#pragma once

#include "sim/SimDefects.h"
#include "sim/SpeedRamp.h"

#include <QVector>

namespace opentop {

// The motion physics of a DBU drive, apart from its registers: the speed ramp, a plausible load
// rate, and the conditions that raise alarms (overload, over speed) and warnings; and the
// defects of a simulated drive: held below its target, a load too high, an alarm while running.
class DbuMotor
{
public:
    struct Input
    {
        double target = 0;         // signed r/min (CCW negative)
        double accelPerSecond = 0; // r/min per second
        double decelPerSecond = 0;
        bool commanded = false;              // a run command with a non-zero target
        double overloadMs = 3000;            // alarm.overload_time
        double loadWarning = 100;            // alarm.load_warning, %
        int loadOffset = 0;                  // console `load`
        const SimDefects* defects = nullptr; // a defective drive's motor
    };
    struct Events
    {
        int alarm = 0;         // alarm code raised in this step, 0 when none
        QVector<int> warnings; // warning codes that became active in this step
    };

    Events step(const Input& input, int dtMs);
    void stop();  // free-run stop at once (alarm)
    void reset(); // power on

    double speed() const { return m_ramp.value(); }
    double load() const { return m_load; }
    double revolutions() const { return m_revolutions; }
    bool warningActive() const { return m_loadWarning || m_speedWarning; }

    static constexpr int kAlarmOverSpeed = 0x05;
    static constexpr int kAlarmOverload = 0x07;
    static constexpr int kWarningOverSpeed = 0x05;
    static constexpr int kWarningLoad = 0x07;

private:
    SpeedRamp m_ramp;
    double m_load = 0;
    double m_overloadMs = 0;
    double m_runningMs = 0; // since the start, for an alarm defect
    double m_revolutions = 0;
    bool m_loadWarning = false;
    bool m_speedWarning = false;
};

} // namespace opentop
