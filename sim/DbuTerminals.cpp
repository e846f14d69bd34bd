#include "sim/DbuTerminals.h"

#include "sim/SimDevice.h"

namespace opentop {

DbuTerminals::DbuTerminals(const SimDevice& device)
    : m_device(device)
{
}

int DbuTerminals::assigned(int function) const
{
    int mask = 0;
    for (int i = 0; i < 4; ++i) {
        const int code = int(m_device.raw(QStringLiteral("io.x%1").arg(i)).value_or(0));
        if ((code & 0x0F) == function && code != 0x10)
            mask |= 1 << i;
    }
    return mask;
}

DbuTerminals::IoCommand DbuTerminals::command(int inputs) const
{
    IoCommand c;
    for (int bit = 0; bit < 3; ++bit) {
        if (assigned(M0 + bit) & inputs)
            c.spno |= 1 << bit;
    }
    const bool first = assigned(Run) & inputs;
    const bool second = assigned(Direction) & inputs;
    if (m_device.raw(QStringLiteral("core.control_mode")).value_or(1) == 1) {
        c.run = first != second; // Mode2: CW/STOP, CCW/STOP
        c.ccw = second;
    } else {
        c.run = first; // Mode1: RUN/STOP, CW/CCW
        if (assigned(Direction))
            c.ccw = second;
    }
    return c;
}

int DbuTerminals::level(int function, const State& s) const
{
    switch (function & 0x0F) {
    case 1:
        return s.alarm;
    case 2:
        return s.reach;
    case 3:
        return s.va;
    case 4:
        return s.speed > 0 && qint64(s.revolutions * kPulsesPerRevolution * 2) % 2 == 0;
    case 5:
        return s.warning;
    case 6:
        return s.speed > 0;
    default:
        return 0;
    }
}

int DbuTerminals::outputs(const State& state) const
{
    const int y0 = level(int(m_device.raw(QStringLiteral("io.y0")).value_or(0)), state);
    const int y1 = level(int(m_device.raw(QStringLiteral("io.y1")).value_or(0)), state);
    return y0 | (y1 << 1);
}

} // namespace opentop
