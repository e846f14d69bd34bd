#pragma once

namespace opentop {

// The DC controller's closed-loop speed regulation as OpenTOP models it (docs/simulator.md,
// docs/errata.md "DC PID units"): every millisecond
//     u = P·e + I·Σe + D·(e − e N ms before),   u in 0.1 % of full PWM duty,
// with e = command − feedback in the speed mode's register units (1/s, or 0.01 V for a
// tachogenerator) and N the D regulation period. The derivative term is updated once per D
// period and held between; the sum stops growing while the output is saturated (anti-windup).
class DcSpeedLoop
{
public:
    struct Gains
    {
        double p = 0;
        double i = 0;
        double d = 0;
        int dPeriodMs = 10;
    };

    // One millisecond: the PWM duty, -1..1.
    double step(double command, double feedback, const Gains& gains);
    void reset();

    static constexpr double kOutputFullScale = 1000; // u at 100 % duty

private:
    double m_sum = 0;
    double m_dTerm = 0;
    double m_dReference = 0; // e at the start of the present D period
    int m_dCount = 0;
    bool m_started = false;
};

} // namespace opentop
