#include "model/tuning/RelayAutotune.h"

#include "model/ModelLog.h"
#include "model/tuning/RelayTuning.h"
#include "model/tuning/TuningDrive.h"

#include <algorithm>
#include <cmath>

namespace opentop {

namespace {

constexpr int kHoldMs = 800;     // each hold of the relay's gain estimate, at least
constexpr int kMaxHoldMs = 4000; // a heavy load's: the speed has not settled in 800 ms
constexpr int kAverageMs = 300;  // the end of a hold that is averaged

double mean(const TuningSamples& s, double sinceMs, double TuningSample::*field,
            double untilMs = 1e300)
{
    double sum = 0;
    int n = 0;
    for (const TuningSample& x : s) {
        if (x.tMs >= sinceMs && x.tMs < untilMs) {
            sum += x.*field;
            ++n;
        }
    }
    return n ? sum / n : 0;
}

} // namespace

RelayAutotune::RelayAutotune(TuningDrive* drive)
    : m_drive(drive)
{
    RunnerStates& states = drive->states();
    states.add(OpenLoop, "open loop", [this] { openLoop(); });
    states.add(Estimate, "estimate", [this] { estimate(); });
    states.add(Relay, "relay", [this] { relay(); });
    states.add(Conclude, "conclude", [this] { conclude(); });
}

void RelayAutotune::start(const TuningRunner::RelayPlan& plan, TuningRunner::Done done)
{
    if (m_drive->refuseIfRunning(done))
        return;
    m_plan = plan;
    m_openScale = 1;
    m_plantGain = 0;
    m_restCurrent = 0;
    m_hold = 0;
    m_u = m_u1 = m_y1 = 0;
    m_u0 = m_d = m_h = 0;
    m_high = false;
    m_drive->begin(std::move(done), OpenLoop);
}

void RelayAutotune::openLoop()
{
    const TuningRunner::Limits& limits = m_drive->limits();
    const QString& unit = m_drive->result().speedUnit;
    if (!(m_plan.speed > 0) || (limits.maxSpeed > 0 && m_plan.speed >= limits.maxSpeed)) {
        m_drive->fail(
            tr("the operating speed must be above 0 and below the test's speed limit %1 %2")
                .arg(limits.maxSpeed)
                .arg(unit),
            false);
        return;
    }
    if (!(m_plan.amplitude > 0 && m_plan.amplitude <= 50)) {
        m_drive->fail(tr("the relay amplitude must be 0–50 % of full output"), false);
        return;
    }
    m_drive->announce(tr("Open loop: finding the output for %1 %2").arg(m_plan.speed).arg(unit));
    m_drive->setMode(m_drive->spec().openLoopMode, [this] {
        m_openScale = m_drive->feedbackScale();
        m_hold = 0;
        m_u = firstOutput();
        m_y1 = 0;
        m_drive->states().go(Estimate);
    });
}

// Half the output that maps the closed-loop command's full range onto full output, so that a
// motor up to 3 times as fast as the range stays within the test's speed limit (1.5 × the
// speed); the second hold corrects it.
double RelayAutotune::firstOutput() const
{
    const DeviceSession* session = m_drive->session();
    const TuningSpec& spec = m_drive->spec();
    const ParameterMeta* meta = session->profile().parameter(spec.command);
    double range = 0;
    if (meta && m_drive->originalMode()) {
        ValueContext c = session->context();
        const auto base = c.parameterRaw;
        const QString modeName = spec.speedMode;
        const qint64 closed = qint64(*m_drive->originalMode());
        c.parameterRaw = [base, modeName, closed](const QString& p) {
            return p == modeName ? std::optional<qint64>(closed) : (base ? base(p) : std::nullopt);
        };
        for (const ValueRange& r : meta->specFor(c).ranges)
            range = std::max(range, r.max * m_drive->closedScale());
    }
    const double full = spec.outputFullScale;
    return range > 0 ? std::clamp(full * m_plan.speed / range / 2, 0.02 * full, 0.9 * full)
                     : 0.3 * full;
}

void RelayAutotune::estimate()
{
    m_drive->setReference(m_drive->nowMs());
    m_drive->result().samples.clear();
    m_drive->command(m_u * m_openScale, [this] { hold(); });
}

// One reading of a hold; the next one at once until the speed no longer moves: the last
// 300 ms against the 300 before (a gain read off a speed still rising makes the model, and
// the relay's output, wrong).
void RelayAutotune::hold()
{
    m_drive->poll([this](const TuningSample& sample) {
        TuningSample s = sample;
        s.command = m_u * m_openScale;
        m_drive->record(s);
        const TuningSamples& samples = m_drive->result().samples;
        const double since = s.tMs - kAverageMs;
        const double y = mean(samples, since, &TuningSample::speed);
        const double before = mean(samples, since - kAverageMs, &TuningSample::speed, since);
        const bool steady =
            std::abs(y - before) <= std::max(0.005 * m_plan.speed, m_drive->closedScale());
        if (s.tMs < kHoldMs || (!steady && s.tMs < kMaxHoldMs)) {
            hold();
            return;
        }
        m_restCurrent = mean(samples, since, &TuningSample::current);
        held(y);
    });
}

// The hold's speed `y` at output m_u: the relay's output, or a second hold first.
void RelayAutotune::held(double y)
{
    const double full = m_drive->spec().outputFullScale;
    const double u = m_u;
    if (m_hold == 0) {
        if (y <= 0) {
            m_drive->fail(tr("the motor did not turn at %1 % output").arg(u * 100 / full));
            return;
        }
        const double u0 = std::clamp(u * m_plan.speed / y, 0.02 * full, 0.9 * full);
        m_plantGain = y / u;
        if (std::abs(u0 - u) < 0.01 * full) {
            m_u0 = u;
            m_high = m_plan.speed > y;
            m_drive->states().go(Relay);
            return;
        }
        m_hold = 1;
        m_u1 = u;
        m_y1 = y;
        m_u = u0;
        m_drive->states().go(Estimate);
        return;
    }
    const double k = std::abs(u - m_u1) >= 0.02 * full && (y - m_y1) / (u - m_u1) > 0
                         ? (y - m_y1) / (u - m_u1)
                         : y / u;
    m_plantGain = k;
    m_u0 = std::clamp(u + (m_plan.speed - y) / k, 0.02 * full, 0.9 * full);
    m_high = m_plan.speed > y;
    m_drive->states().go(Relay);
}

void RelayAutotune::relay()
{
    const double full = m_drive->spec().outputFullScale;
    m_d = m_plan.amplitude / 100 * full;
    if (m_u0 + m_d > full || m_u0 - m_d < 0) {
        m_drive->fail(tr("the operating speed needs %1 % output: no room for ±%2 % around it")
                          .arg(m_u0 * 100 / full, 0, 'f', 1)
                          .arg(m_plan.amplitude));
        return;
    }
    m_drive->announce(tr("Relay test around %1 %2 (output %3 % ± %4 %)")
                          .arg(m_plan.speed)
                          .arg(m_drive->result().speedUnit)
                          .arg(m_u0 * 100 / full, 0, 'f', 1)
                          .arg(m_plan.amplitude));
    m_drive->result().samples.clear();
    m_drive->setReference(m_drive->nowMs());
    m_h = m_plan.hysteresis > 0 ? m_plan.hysteresis : 0.01 * m_plan.speed;
    m_drive->command((m_high ? m_u0 + m_d : m_u0 - m_d) * m_openScale, [this] { swing(); });
}

// One reading of the relay: the output switched when the speed leaves the hysteresis band on
// the other side; at each upward crossing the oscillation is judged.
void RelayAutotune::swing()
{
    m_drive->poll([this](const TuningSample& sample) {
        TuningSample s = sample;
        s.command = (m_high ? m_u0 + m_d : m_u0 - m_d) * m_openScale;
        m_drive->record(s);
        TuningRunner::Result& r = m_drive->result();
        const double e = m_plan.speed - s.speed;
        const bool next = e > m_h ? true : e < -m_h ? false : m_high;
        const int n = r.samples.size();
        const bool upCrossing =
            n > 1 && r.samples[n - 2].speed < m_plan.speed && s.speed >= m_plan.speed;
        if (upCrossing) {
            const RelayAnalysis a =
                RelayAnalysis::analyse(r.samples, m_plan.speed, m_d, m_h, m_plan.cycles);
            if (a.steady || a.busPaced) { // the rest of its checks: conclude()
                r.relay = a;
                m_drive->states().go(Conclude);
                return;
            }
        }
        if (s.tMs > m_plan.maxMs) {
            const RelayAnalysis a =
                RelayAnalysis::analyse(r.samples, m_plan.speed, m_d, m_h, m_plan.cycles);
            r.relay = a;
            r.advice = a.advice;
            m_drive->fail(tr("no steady oscillation within %1 s: %2")
                              .arg(m_plan.maxMs / 1000.0)
                              .arg(a.error.isEmpty() ? tr("try a larger amplitude") : a.error));
            return;
        }
        if (next == m_high) {
            swing();
            return;
        }
        m_high = next;
        m_drive->command((next ? m_u0 + m_d : m_u0 - m_d) * m_openScale, [this] { swing(); });
    });
}

void RelayAutotune::conclude()
{
    RelayTuning::Input in;
    in.relay = m_drive->result().relay;
    in.plantGain = m_plantGain;
    in.closedScale = m_drive->closedScale();
    in.openScale = m_openScale;
    in.d = m_d;
    in.restCurrent = m_restCurrent;
    in.currentLimit = m_drive->currentLimit();
    in.speed = m_plan.speed;
    in.rule = m_plan.rule;
    RelayTuning::conclude(m_drive->spec(), in, &m_drive->result());
    const TuningRunner::Result& r = m_drive->result();
    qCDebug(lcModel) << "autotune: Ku" << r.relay.ultimateGain << "Tu" << r.relay.periodMs
                     << "readings/period" << r.relay.readingsPerPeriod << "bus delay"
                     << r.busDelayMs << "model tau" << r.plant.tauMs << "dead" << r.plant.deadMs
                     << "A per output" << r.plant.currentPerOutput << "own Ku" << r.ultimateGain
                     << "Tu" << r.ultimatePeriodMs << "proposal" << r.proposal.toString()
                     << r.error;
    if (!r.ok) {
        m_drive->fail(tr("the relay result was refused: %1").arg(r.error));
        return;
    }
    m_drive->finish();
}

} // namespace opentop
