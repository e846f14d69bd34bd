#include "tuning/StepMetrics.h"

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
    std::optional<double> t10;
    double peak = -1e300;
    for (const TuningSample& s : after) {
        const double p = progress(s);
        if (!t10 && p >= 0.1)
            t10 = s.tMs;
        if (t10 && !m.riseMs && p >= 0.9)
            m.riseMs = s.tMs - *t10;
        peak = std::max(peak, p);
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
    if (last + 1 < after.size() && last < after.size() - 2)
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
