#pragma once

#include <QString>

namespace opentop {

// A speed controller's PID coefficients as its registers hold them (TuningSpec: the form).
struct PidGains
{
    double p = 0;
    double i = 0;
    double d = 0;
    int dPeriodMs = 10;

    bool operator==(const PidGains& o) const
    {
        return p == o.p && i == o.i && d == o.d && dPeriodMs == o.dPeriodMs;
    }
    bool operator!=(const PidGains& o) const { return !(*this == o); }
    // "P 0.1000, I 0.0100, D 0.0000, D period 10 ms"
    QString toString() const;
};

} // namespace opentop
