#include "model/tuning/StepMetrics.h"

#include <algorithm>
#include <cmath>

namespace opentop {

StepMetrics StepMetrics::measure(const TuningSamples& samples, double from, double to)
{
    StepMetrics m;
    const double step = to - from;
    TuningSamples after;
    for (const TuningSample& s : samples) {
        if (s.tMs >= 0)
            after << s;
    }
    if (std::abs(step) <= 0 || after.size() < 4) {
        m.error = std::abs(step) <= 0 ? tr("the step has no height (from = to)")
                                      : tr("too few samples after the step (%1)").arg(after.size());
        return m;
    }
    // Progress along the step, 0 at `from`, 1 at `to`.
    const auto progress = [&](const TuningSample& s) { return (s.speed - from) / step; };
    // The rise from the last reading before the step, if there is one, with crossings
    // interpolated between readings.
    TuningSamples seq;
    for (const TuningSample& s : samples) {
        if (s.tMs < 0)
            seq = {s};
    }
    seq += after;
    const auto crossing = [&](int k, double level) {
        if (k == 0)
            return seq[0].tMs;
        const double pa = progress(seq[k - 1]), pb = progress(seq[k]);
        const double f = pb > pa ? (level - pa) / (pb - pa) : 1;
        return seq[k - 1].tMs + std::clamp(f, 0.0, 1.0) * (seq[k].tMs - seq[k - 1].tMs);
    };
    int k90 = -1;
    for (int k = 0; k < seq.size() && k90 < 0; ++k) {
        if (progress(seq[k]) >= 0.9)
            k90 = k;
    }
    int k10 = -1; // the first reading at or beyond 10 % after the last one below it
    for (int k = 0; k < k90; ++k) {
        if (progress(seq[k]) < 0.1)
            k10 = k + 1;
    }
    // No reading below 10 %: the speed was not at `from` when the step began.
    if (k90 >= 0 && k10 >= 1)
        m.riseMs = crossing(k90, 0.9) - crossing(k10, 0.1);
    double peak = -1e300;
    for (const TuningSample& s : after) {
        peak = std::max(peak, progress(s));
        m.peakCurrent = std::max(m.peakCurrent, std::abs(s.current));
    }
    m.overshootPercent = std::max(0.0, (peak - 1) * 100);
    // Settled from the first sample after which every sample stays within the band.
    const double band = kSettlingBand * std::abs(step);
    int last = -1;
    for (int k = 0; k < after.size(); ++k) {
        if (std::abs(after[k].speed - to) > band)
            last = k;
    }
    // An oscillation passing through the band as the record ends is not settled: the stay
    // must be long enough to be seen (a share of the record, and a few readings).
    const int held = int(after.size()) - (last + 1);
    if (held >= kSettledReadings &&
        after.last().tMs - after[last + 1].tMs >= kSettledHoldShare * after.last().tMs)
        m.settlingMs = after[last + 1].tMs;
    const int tail = std::max(1, int(after.size()) / 4);
    double sum = 0;
    for (int k = after.size() - tail; k < after.size(); ++k)
        sum += after[k].speed;
    m.steadyStateError = sum / tail - to;
    m.recordMs = after.last().tMs;
    m.valid = true;
    return m;
}

} // namespace opentop
