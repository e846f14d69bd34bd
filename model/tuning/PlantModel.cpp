#include "model/tuning/PlantModel.h"

#include "model/tuning/TuningSpec.h"

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

double PlantModel::currentPerOutputOf(const TuningSamples& relay, double outputScale, double d,
                                      double tauMs)
{
    if (relay.size() < 3 || !(d > 0) || !(outputScale > 0))
        return 0;
    // A plain reading's interval (no switch between): the time a switch's write took is the
    // rest of the interval around it.
    QVector<double> plain;
    for (int k = 1; k < relay.size(); ++k) {
        if (relay[k].command == relay[k - 1].command)
            plain << relay[k].tMs - relay[k - 1].tMs;
    }
    std::sort(plain.begin(), plain.end());
    const double reading = plain.isEmpty() ? 0 : plain[plain.size() / 2];
    QVector<double> estimates;
    for (int k = 1; k < relay.size(); ++k) {
        const double before = relay[k - 1].command / outputScale;
        const double after = relay[k].command / outputScale;
        if (before == after || std::abs(std::abs(after - before) - 2 * d) > 0.01 * d)
            continue;
        const double sinceSwitch =
            std::max(0.0, relay[k].tMs - relay[k - 1].tMs - reading); // the write's share
        const double decay = tauMs > 0 ? std::min(3.0, std::exp(sinceSwitch / tauMs)) : 1;
        estimates << (std::abs(relay[k].current) + std::abs(relay[k - 1].current)) * decay /
                         (2 * d);
    }
    if (estimates.isEmpty())
        return 0;
    std::sort(estimates.begin(), estimates.end());
    return estimates[estimates.size() / 2];
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
    const bool limited = currentPerOutput > 0 && currentLimit > 0;
    // How far the output may lead the shaft before the current reaches the limit, either way.
    const double up = limited ? std::max(0.0, (currentLimit - restCurrent) / currentPerOutput) : 0;
    const double down =
        limited ? std::max(0.0, (currentLimit + restCurrent) / currentPerOutput) : 0;
    // At rest on `from`: the output that holds it, carried by the integral where there is one.
    const double u0 = std::clamp(from / gain, -full, full);
    QVector<double> pipe(dead + 1, from); // the measurement, `dead` periods behind the shaft
    int head = 0;
    double x = from; // the shaft
    double y = from; // what the controller reads
    double sum = g.i > 0 ? u0 / g.i : 0;
    const double offset = g.i > 0 ? 0 : u0;
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
        const double needed = x / gain;
        const double applied = limited ? std::clamp(u, needed - down, needed + up) : u;
        x += (gain * applied - x) * period / std::max(period, tauMs);
        pipe[head] = x;
        head = (head + 1) % pipe.size();
        y = pipe[head]; // `dead` periods old
        if (t >= nextSample) {
            const double current =
                currentPerOutput > 0 ? std::abs(restCurrent + currentPerOutput * (applied - needed))
                                     : 0;
            out.append({t, to, y, current, u});
            nextSample += sampleMs;
        }
    }
    return out;
}

} // namespace opentop
