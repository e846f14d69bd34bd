#pragma once

namespace opentop {

// A signed speed that follows a target at a limited rate: `up` while its magnitude grows in the
// same direction, `down` while it shrinks or reverses (units per second).
class SpeedRamp
{
public:
    double value() const { return m_value; }
    // Rate of change during the last step, units per second.
    double rate() const { return m_rate; }
    void set(double value);
    void step(double target, double upPerSecond, double downPerSecond, int dtMs);

private:
    double m_value = 0;
    double m_rate = 0;
};

} // namespace opentop
