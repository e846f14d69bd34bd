#include "tuning/RelayAnalysis.h"

#include <algorithm>
#include <cmath>

namespace opentop {

RelayAnalysis RelayAnalysis::analyse(const TuningSamples& samples, double setpoint,
                                     double relayAmplitude, double hysteresis, int minCycles)
{
    RelayAnalysis r;
    // Upward crossings of the set point mark the cycles.
    QVector<int> ups;
    for (int k = 1; k < samples.size(); ++k) {
        if (samples[k - 1].speed < setpoint && samples[k].speed >= setpoint)
            ups << k;
    }
    const auto crossing = [&](int k) {
        const TuningSample& a = samples[k - 1];
        const TuningSample& b = samples[k];
        const double f = (setpoint - a.speed) / (b.speed - a.speed);
        return a.tMs + f * (b.tMs - a.tMs);
    };
    // The first cycle is the approach: leave it out.
    const int usable = int(ups.size()) - 2;
    if (usable < minCycles) {
        r.error = tr("no steady oscillation: %1 full cycles around %2, %3 needed")
                      .arg(std::max(0, usable))
                      .arg(setpoint)
                      .arg(minCycles);
        return r;
    }
    const int first = int(ups.size()) - 1 - std::min(usable, 2 * minCycles);
    QVector<double> periods;
    QVector<double> amplitudes;
    for (int c = first; c + 1 < ups.size(); ++c) {
        periods << crossing(ups[c + 1]) - crossing(ups[c]);
        double lo = 1e300, hi = -1e300;
        for (int k = ups[c]; k < ups[c + 1]; ++k) {
            lo = std::min(lo, samples[k].speed);
            hi = std::max(hi, samples[k].speed);
        }
        amplitudes << (hi - lo) / 2;
    }
    const auto mean = [](const QVector<double>& v) {
        double s = 0;
        for (double x : v)
            s += x;
        return s / v.size();
    };
    r.periodMs = mean(periods);
    r.amplitude = mean(amplitudes);
    r.cycles = int(periods.size());
    for (double p : periods)
        r.spread = std::max(r.spread, std::abs(p - r.periodMs) / r.periodMs);
    for (double a : amplitudes)
        r.spread = std::max(r.spread, std::abs(a - r.amplitude) / r.amplitude);
    if (r.amplitude <= hysteresis || r.periodMs <= 0) {
        r.error = tr("the oscillation (±%1) is no larger than the hysteresis (%2)")
                      .arg(r.amplitude, 0, 'f', 1)
                      .arg(hysteresis);
        return r;
    }
    if (r.spread > 0.35) {
        r.error = tr("the oscillation is not steady: periods or amplitudes differ by %1 %")
                      .arg(std::lround(r.spread * 100));
        return r;
    }
    const double a = std::sqrt(r.amplitude * r.amplitude - hysteresis * hysteresis);
    r.ultimateGain = 4 * relayAmplitude / (M_PI * a);
    r.ok = true;
    return r;
}

} // namespace opentop
