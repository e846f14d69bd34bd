#include "tuning/PlantModel.h"

#include "tuning/TuningSpec.h"

#include <QVector>

#include <algorithm>
#include <cmath>

namespace opentop {

PlantModel PlantModel::fromRelay(double gain, double ku, double tuMs, double busDelayMs,
                                 double minDeadMs)
{
    PlantModel m;
    const double kku = std::abs(gain) * ku;
    if (!(tuMs > 0) || !(kku > 1)) {
        m.error = tr("the relay test gives no usable model (K·Ku = %1, Tu = %2 ms)")
                      .arg(kku, 0, 'f', 2)
                      .arg(tuMs, 0, 'f', 1);
        return m;
    }
    const double w = 2 * M_PI / tuMs;
    m.gain = gain;
    m.tauMs = std::sqrt(kku * kku - 1) / w;
    const double dead = (M_PI - std::atan(m.tauMs * w)) / w;
    m.deadMs = std::max(minDeadMs, dead - busDelayMs);
    m.valid = true;
    return m;
}

bool PlantModel::ultimate(double* ku, double* tuMs) const
{
    if (!valid || deadMs <= 0)
        return false;
    // atan(τω) + θω rises from 0 to beyond π on (0, π/θ]: bisection.
    double lo = 1e-9, hi = M_PI / deadMs;
    for (int k = 0; k < 100; ++k) {
        const double mid = (lo + hi) / 2;
        (std::atan(tauMs * mid) + deadMs * mid < M_PI ? lo : hi) = mid;
    }
    const double w = (lo + hi) / 2;
    *ku = std::sqrt(1 + tauMs * w * tauMs * w) / std::abs(gain);
    *tuMs = 2 * M_PI / w;
    return true;
}

TuningSamples PlantModel::simulateStep(const PidGains& g, const TuningSpec& spec, double from,
                                       double to, double durationMs, double sampleMs) const
{
    TuningSamples out;
    if (!valid)
        return out;
    const double period = std::max(1, spec.periodMs);
    const double full = spec.outputFullScale;
    const int dead = std::max(0, int(std::lround(deadMs / period)));
    // At rest on `from`: the output that holds it, carried by the integral where there is one.
    const double u0 = std::clamp(from / gain, -full, full);
    QVector<double> pipe(dead + 1, u0);
    int head = 0;
    double y = from;
    double sum = g.i > 0 ? (u0 - g.p * 0) / g.i : 0;
    double offset = g.i > 0 ? 0 : u0;
    double dTerm = 0;
    double dRef = to - y;
    int dCount = 0;
    const int dPeriod = std::max(1, int(std::lround(g.dPeriodMs / period)));
    double nextSample = 0;
    for (double t = 0; t <= durationMs; t += period) {
        const double e = to - y;
        if (++dCount >= dPeriod) {
            dTerm = g.d * (e - dRef);
            dRef = e;
            dCount = 0;
        }
        const double raw = offset + g.p * e + g.i * (sum + e) + dTerm;
        const double u = std::clamp(raw, -full, full);
        if (u == raw || (raw > 0) != (e > 0))
            sum += e;
        pipe[head] = u;
        head = (head + 1) % pipe.size();
        const double applied = pipe[head]; // `dead` periods old
        y += (gain * applied - y) * period / std::max(period, tauMs);
        if (t >= nextSample) {
            out.append({t, to, y, 0, u});
            nextSample += sampleMs;
        }
    }
    return out;
}

} // namespace opentop
