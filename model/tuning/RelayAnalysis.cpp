#include "model/tuning/RelayAnalysis.h"

#include <algorithm>
#include <cmath>

namespace opentop {

namespace {

double mean(const QVector<double>& v)
{
    double s = 0;
    for (double x : v)
        s += x;
    return v.isEmpty() ? 0 : s / v.size();
}

double spread(const QVector<double>& v, double m)
{
    double s = 0;
    for (double x : v)
        s = std::max(s, m > 0 ? std::abs(x - m) / m : 0);
    return s;
}

} // namespace

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
        r.advice = tr("Raise the relay amplitude, or choose an operating speed that leaves the "
                      "output room on both sides.");
        return r;
    }
    // The last `minCycles` cycles: a host that stalls now and then spoils fewer windows.
    const int first = int(ups.size()) - 1 - minCycles;
    QVector<double> periods;
    QVector<double> amplitudes;
    QVector<double> asymmetries;
    for (int c = first; c + 1 < ups.size(); ++c) {
        const double up = crossing(ups[c]);
        const double next = crossing(ups[c + 1]);
        periods << next - up;
        double lo = 1e300, hi = -1e300;
        double down = next;
        for (int k = ups[c]; k < ups[c + 1]; ++k) {
            lo = std::min(lo, samples[k].speed);
            hi = std::max(hi, samples[k].speed);
            if (down == next && k > ups[c] && samples[k - 1].speed >= setpoint &&
                samples[k].speed < setpoint)
                down = crossing(k);
        }
        amplitudes << (hi - lo) / 2;
        asymmetries << std::abs((down - up) - (next - down)) / (next - up);
    }
    r.periodMs = mean(periods);
    r.amplitude = mean(amplitudes);
    r.cycles = int(periods.size());
    r.periodSpread = spread(periods, r.periodMs);
    r.amplitudeSpread = spread(amplitudes, r.amplitude);
    r.asymmetry = mean(asymmetries);
    const int from = ups[first], to = ups.last();
    r.readingMs = to > from ? (samples[to].tMs - samples[from].tMs) / (to - from) : 0;
    r.readingsPerPeriod = r.readingMs > 0 ? r.periodMs / r.readingMs : 0;
    if (r.amplitude <= hysteresis || r.periodMs <= 0) {
        r.error = tr("the oscillation (±%1) is no larger than the hysteresis (%2)")
                      .arg(r.amplitude, 0, 'f', 1)
                      .arg(hysteresis);
        r.advice = tr("Raise the relay amplitude.");
        return r;
    }
    const double a = std::sqrt(r.amplitude * r.amplitude - hysteresis * hysteresis);
    r.ultimateGain = 4 * relayAmplitude / (M_PI * a);
    // First: a relay the bus paces is irregular too, and more cycles will not help.
    if (r.readingsPerPeriod < kMinReadingsPerPeriod) {
        r.busPaced = true;
        r.error = tr("the oscillation's period, %1 ms, holds only %2 readings (one every %3 ms): "
                     "at least %4 are needed, or its period and amplitude are the bus's rather "
                     "than the motor's")
                      .arg(r.periodMs, 0, 'f', 1)
                      .arg(r.readingsPerPeriod, 0, 'f', 1)
                      .arg(r.readingMs, 0, 'f', 1)
                      .arg(kMinReadingsPerPeriod);
        r.advice = tr("Raise the line rate (115200 bit/s if every drive on the bus allows it) "
                      "or stop polling other drives on this bus during the test; a larger "
                      "relay amplitude or another speed does not change this.");
        return r;
    }
    if (r.periodSpread > kMaxPeriodSpread || r.amplitudeSpread > kMaxAmplitudeSpread) {
        r.error = tr("the oscillation is not steady: periods differ by %1 %, amplitudes by %2 % "
                     "(at most %3 % and %4 %)")
                      .arg(std::lround(r.periodSpread * 100))
                      .arg(std::lround(r.amplitudeSpread * 100))
                      .arg(std::lround(kMaxPeriodSpread * 100))
                      .arg(std::lround(kMaxAmplitudeSpread * 100));
        r.advice = tr("Raise the relay amplitude so that the oscillation stands out of friction "
                      "and load changes, keep the load steady during the test, and stop polling "
                      "other drives on this bus meanwhile.");
        return r;
    }
    r.steady = true;
    if (r.asymmetry > kMaxAsymmetry) {
        r.error = tr("the oscillation is lopsided: its time above and below %1 differ by %2 % of "
                     "the period (at most %3 %)")
                      .arg(setpoint)
                      .arg(std::lround(r.asymmetry * 100))
                      .arg(std::lround(kMaxAsymmetry * 100));
        r.advice = tr("The output for the operating speed was misjudged or the load changed: "
                      "keep the load steady, choose an operating speed further from standstill "
                      "and from full output, and repeat the test.");
        return r;
    }
    r.ok = true;
    return r;
}

} // namespace opentop
