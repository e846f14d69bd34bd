#include "model/tuning/TuningRunner.h"

#include "model/ModelLog.h"
#include "model/session/DeviceSession.h"
#include "model/tuning/RelayTuning.h"

#include <QPointer>
#include <QTimer>

#include <algorithm>
#include <cmath>

namespace opentop {

namespace {

constexpr int kMaxFailedPolls = 5;
constexpr int kHoldMs = 800;       // each hold of the relay's gain estimate, at least
constexpr int kMaxHoldMs = 4000;   // a heavy load's: the speed has not settled in 800 ms
constexpr int kAverageMs = 300;    // the end of a hold that is averaged
constexpr int kSettledForMs = 300; // at `from` this long before the step

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

struct TuningRunner::Context
{
    Result result;
    QElapsedTimer clock;
    double origin = 0; // the runner's clock at the start, when it has one
    double t0 = 0;     // reference moment (step, relay start), ms since the start
    std::optional<double> originalMode;
    std::optional<double> originalCommLoss;
    bool modeChanged = false;
    bool commLossChanged = false;
    bool finishing = false;
    bool cancelled = false;
    int failedPolls = 0;
    double closedScale = 1;  // engineering per raw of the closed-loop speed command
    double openScale = 1;    // engineering per raw of the open-loop (duty) command
    double plantGain = 0;    // feedback engineering per output raw
    double restCurrent = 0;  // A, at the last hold before the relay
    double currentLimit = 0; // A, the drive's (0: unknown)
    double settledSince = -1;
    int polls = 0;
    bool high = false;
    double u0 = 0;
    // The step that repeats (a poll and what follows it). It holds the context, so it is
    // cleared when the test ends or the runner goes, which frees both.
    std::function<void()> loop;
    // While the stop is awaited: what follows when the drive no longer answers.
    std::function<void()> stopUnconfirmed;
};

TuningRunner::TuningRunner(DeviceSession* session, const TuningSpec& spec, QObject* parent)
    : QObject(parent)
    , m_session(session)
    , m_spec(spec)
{
}

TuningRunner::~TuningRunner()
{
    // Gone while a test runs (its page or command torn down): the motor must not go on. The
    // stop is sent without waiting; the session's callbacks find this runner gone.
    if (m_done && m_session && m_ctx && !m_ctx->finishing) {
        DeviceSession::WriteOptions options;
        options.explicitCommand = true;
        options.verify = false;
        m_session->write(m_spec.command, QStringLiteral("0"), options,
                         [](const DeviceSession::Outcome&) {});
    }
    if (m_ctx) {
        m_ctx->loop = nullptr;
        m_ctx->stopUnconfirmed = nullptr;
    }
}

double TuningRunner::nowMs() const
{
    return m_clock ? m_clock() - m_ctx->origin : m_ctx->clock.nsecsElapsed() / 1e6;
}

double TuningRunner::modeOf() const
{
    return m_session->cachedValue(m_spec.speedMode).raw;
}

double TuningRunner::feedbackScale() const
{
    const ParameterMeta* meta = m_session->profile().parameter(m_spec.command);
    return meta ? meta->specFor(m_session->context()).scale : 1;
}

void TuningRunner::readGains(GainsDone done)
{
    m_session->readMany(m_spec.gainParameters(),
                        [self = QPointer(this), this, done](const auto& r) {
                            if (!self)
                                return;
                            PidGains g;
                            for (const QString& name : m_spec.gainParameters()) {
                                const DeviceSession::Outcome o = r.results.value(name);
                                if (!o.ok) {
                                    done(false, g, o.error);
                                    return;
                                }
                            }
                            g.p = r.results.value(m_spec.gainP).value.number;
                            g.i = r.results.value(m_spec.gainI).value.number;
                            g.d = r.results.value(m_spec.gainD).value.number;
                            g.dPeriodMs = int(r.results.value(m_spec.dPeriod).value.number);
                            done(true, g, QString());
                        });
}

void TuningRunner::writeGains(const PidGains& gains, GainsDone done)
{
    writeGainsFrom(gains, 0, std::move(done));
}

void TuningRunner::writeGainsFrom(const PidGains& gains, int k, GainsDone done)
{
    const QVector<QPair<QString, double>> values = {{m_spec.gainP, gains.p},
                                                    {m_spec.gainI, gains.i},
                                                    {m_spec.gainD, gains.d},
                                                    {m_spec.dPeriod, double(gains.dPeriodMs)}};
    if (k == values.size()) {
        readGains(done);
        return;
    }
    DeviceSession::WriteOptions options;
    m_session->write(
        values[k].first, QString::number(values[k].second, 'g', 7), options,
        [self = QPointer(this), this, k, done, gains](const DeviceSession::Outcome& o) {
            if (!self)
                return;
            if (!o.ok) {
                done(false, gains, o.error);
                return;
            }
            writeGainsFrom(gains, k + 1, done);
        });
}

void TuningRunner::storeGains(std::function<void(bool, const QString&)> done)
{
    DeviceSession::WriteOptions options;
    options.explicitCommand = true;
    options.verify = false;
    m_session->write(m_spec.store, QString::number(m_spec.storeValue), options,
                     [done](const DeviceSession::Outcome& o) { done(o.ok, o.error); });
}

void TuningRunner::writeNumber(const QString& parameter, double value,
                               std::function<void(bool)> then)
{
    DeviceSession::WriteOptions options;
    options.explicitCommand = true;
    const auto ctx = m_ctx;
    m_session->write(parameter, QString::number(value, 'g', 10), options,
                     [self = QPointer(this), this, ctx, then](const DeviceSession::Outcome& o) {
                         if (!self || ctx != m_ctx)
                             return;
                         if (!o.ok && !ctx->finishing) {
                             fail(o.error);
                             return;
                         }
                         then(o.ok);
                     });
}

void TuningRunner::command(double engineering, std::function<void()> then)
{
    const double step = feedbackScale(); // whole raw units of the present mode
    writeNumber(m_spec.command, step > 0 ? std::round(engineering / step) * step : engineering,
                [then](bool) { then(); });
}

void TuningRunner::setMode(int mode, std::function<void()> then)
{
    writeNumber(m_spec.speedMode, mode, [this, then](bool) {
        m_ctx->modeChanged = true;
        then();
    });
}

void TuningRunner::begin(Done done, std::function<void()> body)
{
    if (m_done) {
        Result r;
        r.error = tr("a tuning test is already running");
        QTimer::singleShot(0, this, [done, r] { done(r); });
        return;
    }
    m_done = std::move(done);
    m_ctx = std::make_shared<Context>();
    m_ctx->clock.start();
    m_ctx->origin = m_clock ? m_clock() : 0;
    const auto ctx = m_ctx;
    emit phase(tr("Reading the drive's settings"));
    m_session->readMany(
        QStringList{m_spec.speedMode, m_spec.commLossTime} + m_spec.gainParameters() +
            (m_spec.currentLimit.isEmpty() ? QStringList() : QStringList{m_spec.currentLimit}),
        [self = QPointer(this), this, ctx, body](const DeviceSession::ReadManyOutcome& r) {
            if (!self || ctx != m_ctx)
                return;
            if (r.failed) {
                ctx->finishing = true; // nothing moved yet
                fail(tr("could not read the drive's settings: %1")
                         .arg(r.results.value(r.order.value(0)).error),
                     false);
                return;
            }
            ctx->originalMode = r.results.value(m_spec.speedMode).value.raw;
            ctx->originalCommLoss = r.results.value(m_spec.commLossTime).value.number;
            if (!m_spec.currentLimit.isEmpty())
                ctx->currentLimit = r.results.value(m_spec.currentLimit).value.number;
            PidGains& g = ctx->result.gains;
            g.p = r.results.value(m_spec.gainP).value.number;
            g.i = r.results.value(m_spec.gainI).value.number;
            g.d = r.results.value(m_spec.gainD).value.number;
            g.dPeriodMs = int(r.results.value(m_spec.dPeriod).value.number);
            if (!m_spec.closedLoop(int(*ctx->originalMode))) {
                ctx->finishing = true;
                QStringList modes;
                const ParameterMeta* modeMeta = m_session->profile().parameter(m_spec.speedMode);
                for (const TuningSpec::ClosedLoopMode& m : m_spec.closedLoopModes) {
                    QString label = QString::number(m.mode);
                    for (const EnumOption& o : modeMeta
                                                   ? modeMeta->specFor(m_session->context()).options
                                                   : QVector<EnumOption>())
                        if (o.value == m.mode)
                            label = QStringLiteral("%1 (%2)").arg(o.label).arg(m.mode);
                    modes << label;
                }
                fail(tr("the drive is not in a closed-loop speed mode: set %1 (%2) to %3 first")
                         .arg(modeMeta ? modeMeta->label : m_spec.speedMode, m_spec.speedMode,
                              modes.join(tr(" or "))),
                     false);
                return;
            }
            ctx->closedScale = feedbackScale();
            const ParameterMeta* unitMeta = m_session->profile().parameter(
                m_spec.closedLoop(int(*ctx->originalMode))->feedback);
            ctx->result.speedUnit =
                unitMeta ? unitMeta->specFor(m_session->context()).unit : QString();
            const double loss = *ctx->originalCommLoss;
            if (loss > 0 && loss <= m_limits.commLossS) {
                body();
                return;
            }
            emit phase(
                tr("Setting the communication-loss braking time to %1 s").arg(m_limits.commLossS));
            writeNumber(m_spec.commLossTime, m_limits.commLossS, [ctx, body](bool) {
                ctx->commLossChanged = true;
                body();
            });
        });
}

void TuningRunner::poll(std::function<void(const TuningSample&)> then)
{
    const auto ctx = m_ctx;
    const int mode = int(modeOf());
    const TuningSpec::ClosedLoopMode* loop =
        m_spec.closedLoop(ctx->originalMode ? int(*ctx->originalMode) : mode);
    const QString feedback = loop ? loop->feedback : QString();
    m_session->readMany(
        {feedback, m_spec.loadCurrent, m_spec.output},
        [self = QPointer(this), this, ctx, feedback,
         then](const DeviceSession::ReadManyOutcome& r) {
            if (!self || ctx != m_ctx)
                return;
            if (r.failed) {
                if (++ctx->failedPolls >= kMaxFailedPolls && !ctx->finishing) {
                    fail(
                        tr("the drive stopped answering: %1").arg(r.results.value(feedback).error));
                    return;
                }
                // Waiting for the stop on a line that is gone: it cannot be confirmed.
                if (ctx->failedPolls >= kMaxFailedPolls && ctx->stopUnconfirmed) {
                    const auto unconfirmed = std::move(ctx->stopUnconfirmed);
                    ctx->stopUnconfirmed = nullptr;
                    unconfirmed();
                    return;
                }
                QTimer::singleShot(10, this, [this, ctx, then] {
                    if (ctx == m_ctx)
                        poll(then);
                });
                return;
            }
            ctx->failedPolls = 0;
            ++ctx->polls;
            TuningSample s;
            s.tMs = nowMs() - ctx->t0;
            s.speed = r.results.value(feedback).value.number;
            s.current = r.results.value(m_spec.loadCurrent).value.number;
            s.output = r.results.value(m_spec.output).value.number;
            if (!ctx->finishing) {
                if (m_limits.maxSpeed > 0 && std::abs(s.speed) > m_limits.maxSpeed) {
                    fail(tr("speed %1 %2 beyond the test's limit %3 %2: stopped at once")
                             .arg(s.speed)
                             .arg(ctx->result.speedUnit)
                             .arg(m_limits.maxSpeed));
                    return;
                }
                if (m_limits.maxCurrent > 0 && std::abs(s.current) > m_limits.maxCurrent) {
                    fail(tr("current %1 A beyond the test's limit %2 A: stopped at once")
                             .arg(s.current)
                             .arg(m_limits.maxCurrent));
                    return;
                }
                if (ctx->cancelled) {
                    fail(tr("cancelled"));
                    return;
                }
            }
            then(s);
        });
}

void TuningRunner::cancel()
{
    if (m_ctx && m_done && !m_ctx->finishing)
        m_ctx->cancelled = true;
}

void TuningRunner::fail(const QString& error, bool aborted)
{
    const auto ctx = m_ctx;
    if (!ctx || (ctx->finishing && !ctx->result.error.isEmpty()))
        return;
    qCDebug(lcModel) << "tuning test ends:" << error;
    ctx->result.ok = false;
    ctx->result.error = error;
    ctx->result.aborted = aborted;
    finish();
}

void TuningRunner::finish()
{
    const auto ctx = m_ctx;
    const bool moved = !(ctx->finishing && !ctx->modeChanged && !ctx->commLossChanged &&
                         ctx->result.samples.isEmpty() && !ctx->result.ok);
    ctx->finishing = true;
    const auto deliver = [this, ctx] {
        if (ctx != m_ctx)
            return;
        Done done = std::move(m_done);
        m_done = nullptr;
        m_ctx.reset();
        ctx->loop = nullptr;
        ctx->stopUnconfirmed = nullptr;
        if (done)
            done(ctx->result);
    };
    const auto restore = [this, ctx, deliver] {
        const auto restoreLoss = [this, ctx, deliver] {
            if (!ctx->commLossChanged) {
                deliver();
                return;
            }
            writeNumber(m_spec.commLossTime, *ctx->originalCommLoss,
                        [deliver](bool) { deliver(); });
        };
        if (!ctx->modeChanged) {
            restoreLoss();
            return;
        }
        writeNumber(m_spec.speedMode, *ctx->originalMode, [restoreLoss](bool) { restoreLoss(); });
    };
    if (!moved) {
        restore();
        return;
    }
    emit phase(tr("Stopping the motor"));
    writeNumber(m_spec.command, 0, [this, ctx, restore](bool sent) {
        waitStopped(nowMs() + m_limits.stopTimeoutMs, [this, ctx, restore, sent](bool stopped) {
            ctx->result.stopConfirmed = sent && stopped;
            ctx->result.stopDetail = ctx->result.stopConfirmed
                                         ? tr("motor stopped (confirmed)")
                                         : tr("the motor could not be confirmed stopped: check it");
            emit phase(ctx->result.stopDetail);
            restore();
        });
    });
}

void TuningRunner::waitStopped(double untilMs, std::function<void(bool)> then)
{
    const auto ctx = m_ctx;
    ctx->stopUnconfirmed = [then] { then(false); };
    poll([this, ctx, untilMs, then](const TuningSample& s) {
        ctx->stopUnconfirmed = nullptr;
        if (std::abs(s.speed) <= 0.5 * ctx->closedScale || std::abs(s.speed) < 1e-9) {
            then(true);
            return;
        }
        if (nowMs() > untilMs) {
            then(false);
            return;
        }
        // On a test's clock time moves with the line alone: waiting would only slow the test.
        QTimer::singleShot(m_clock ? 0 : 20, this, [this, ctx, untilMs, then] {
            if (ctx == m_ctx)
                waitStopped(untilMs, then);
        });
    });
}

// --- step test -------------------------------------------------------------------------------

void TuningRunner::startStep(const StepPlan& plan, Done done)
{
    begin(std::move(done), [this, plan] {
        const auto ctx = m_ctx;
        ctx->result.from = plan.from;
        ctx->result.to = plan.to;
        if (plan.from < 0 || plan.to < 0 || plan.from == plan.to) {
            fail(tr("a step test runs forward from one speed to another: from and to must "
                    "differ and be 0 or more"),
                 false);
            return;
        }
        for (double v : {plan.from, plan.to}) {
            if (m_limits.maxSpeed > 0 && v > m_limits.maxSpeed) {
                fail(tr("%1 %2 is beyond the test's speed limit %3 %2")
                         .arg(v)
                         .arg(ctx->result.speedUnit)
                         .arg(m_limits.maxSpeed),
                     false);
                return;
            }
        }
        emit phase(tr("Running to %1 %2").arg(plan.from).arg(ctx->result.speedUnit));
        if (plan.from == 0) {
            stepRecord(plan);
            return;
        }
        command(plan.from, [this, plan] { stepApproach(plan); });
    });
}

void TuningRunner::stepApproach(const StepPlan& plan)
{
    const auto ctx = m_ctx;
    poll([this, ctx, plan](const TuningSample& sample) {
        TuningSample s = sample;
        s.command = plan.from;
        ctx->result.samples << s;
        emit sampled(s);
        const double band =
            std::max(StepMetrics::kSettlingBand * std::abs(plan.to - plan.from), ctx->closedScale);
        const bool near = std::abs(s.speed - plan.from) <= band;
        ctx->settledSince = near ? (ctx->settledSince < 0 ? s.tMs : ctx->settledSince) : -1;
        if ((near && s.tMs - ctx->settledSince >= kSettledForMs) || s.tMs >= plan.settleMs) {
            stepRecord(plan);
            return;
        }
        stepApproach(plan);
    });
}

void TuningRunner::stepRecord(const StepPlan& plan)
{
    const auto ctx = m_ctx;
    const double now = nowMs();
    for (TuningSample& s : ctx->result.samples)
        s.tMs -= now - ctx->t0; // the approach before the step: negative times
    ctx->t0 = now;
    emit phase(tr("Step to %1 %2").arg(plan.to).arg(ctx->result.speedUnit));
    ctx->loop = [this, ctx, plan] {
        poll([this, ctx, plan](const TuningSample& sample) {
            TuningSample s = sample;
            s.command = plan.to;
            ctx->result.samples << s;
            emit sampled(s);
            if (s.tMs < plan.recordMs) {
                ctx->loop();
                return;
            }
            ctx->result.metrics = StepMetrics::measure(ctx->result.samples, plan.from, plan.to);
            ctx->result.ok = ctx->result.metrics.valid;
            ctx->result.error = ctx->result.metrics.error;
            finish();
        });
    };
    command(plan.to, [ctx] { ctx->loop(); });
}

// --- relay autotune --------------------------------------------------------------------------

void TuningRunner::startAutotune(const RelayPlan& plan, Done done)
{
    begin(std::move(done), [this, plan] {
        const auto ctx = m_ctx;
        if (!(plan.speed > 0) || (m_limits.maxSpeed > 0 && plan.speed >= m_limits.maxSpeed)) {
            fail(tr("the operating speed must be above 0 and below the test's speed limit %1 %2")
                     .arg(m_limits.maxSpeed)
                     .arg(ctx->result.speedUnit),
                 false);
            return;
        }
        if (!(plan.amplitude > 0 && plan.amplitude <= 50)) {
            fail(tr("the relay amplitude must be 0–50 % of full output"), false);
            return;
        }
        emit phase(tr("Open loop: finding the output for %1 %2")
                       .arg(plan.speed)
                       .arg(ctx->result.speedUnit));
        setMode(m_spec.openLoopMode, [this, ctx, plan] {
            ctx->openScale = feedbackScale();
            // First guess: half the output that maps the closed-loop command's full range onto
            // full output, so that a motor up to 3 times as fast as the range stays within the
            // test's speed limit (1.5 × the speed); the second hold corrects it.
            const ParameterMeta* meta = m_session->profile().parameter(m_spec.command);
            double range = 0;
            if (meta && ctx->originalMode) {
                ValueContext c = m_session->context();
                const auto base = c.parameterRaw;
                const QString modeName = m_spec.speedMode;
                const qint64 closed = qint64(*ctx->originalMode);
                c.parameterRaw = [base, modeName, closed](const QString& p) {
                    return p == modeName ? std::optional<qint64>(closed)
                                         : (base ? base(p) : std::nullopt);
                };
                for (const ValueRange& r : meta->specFor(c).ranges)
                    range = std::max(range, r.max * ctx->closedScale);
            }
            const double full = m_spec.outputFullScale;
            const double u1 =
                range > 0 ? std::clamp(full * plan.speed / range / 2, 0.02 * full, 0.9 * full)
                          : 0.3 * full;
            relayEstimate(plan, 0, u1, 0);
        });
    });
}

void TuningRunner::relayEstimate(const RelayPlan& plan, int stage, double u, double y1)
{
    const auto ctx = m_ctx;
    ctx->t0 = nowMs();
    ctx->result.samples.clear();
    ctx->loop = [this, ctx, plan, stage, u, y1] {
        poll([this, ctx, plan, stage, u, y1](const TuningSample& sample) {
            TuningSample s = sample;
            s.command = u * ctx->openScale;
            ctx->result.samples << s;
            emit sampled(s);
            // Held until the speed no longer moves: the last 300 ms against the 300 before
            // (a gain read off a speed still rising makes the model, and u0, wrong).
            const double since = s.tMs - kAverageMs;
            const double y = mean(ctx->result.samples, since, &TuningSample::speed);
            const double before =
                mean(ctx->result.samples, since - kAverageMs, &TuningSample::speed, since);
            const bool steady =
                std::abs(y - before) <= std::max(0.005 * plan.speed, ctx->closedScale);
            if (s.tMs < kHoldMs || (!steady && s.tMs < kMaxHoldMs)) {
                ctx->loop();
                return;
            }
            ctx->restCurrent = mean(ctx->result.samples, since, &TuningSample::current);
            const double full = m_spec.outputFullScale;
            if (stage == 0) {
                if (y <= 0) {
                    fail(tr("the motor did not turn at %1 % output").arg(u * 100 / full));
                    return;
                }
                const double u0 = std::clamp(u * plan.speed / y, 0.02 * full, 0.9 * full);
                ctx->plantGain = y / u;
                if (std::abs(u0 - u) < 0.01 * full) {
                    ctx->u0 = u;
                    relayRun(plan, u, plan.speed > y);
                    return;
                }
                ctx->u0 = u0;
                ctx->high = false;
                // Second point; y1 carries the first's speed, `u` below its output.
                ctx->settledSince = u;
                relayEstimate(plan, 1, u0, y);
                return;
            }
            const double u1 = ctx->settledSince;
            const double k = std::abs(u - u1) >= 0.02 * full && (y - y1) / (u - u1) > 0
                                 ? (y - y1) / (u - u1)
                                 : y / u;
            ctx->plantGain = k;
            const double u0 = std::clamp(u + (plan.speed - y) / k, 0.02 * full, 0.9 * full);
            ctx->u0 = u0;
            relayRun(plan, u0, plan.speed > y);
        });
    };
    command(u * ctx->openScale, [ctx] { ctx->loop(); });
}

void TuningRunner::relayRun(const RelayPlan& plan, double u0, bool high)
{
    const auto ctx = m_ctx;
    const double full = m_spec.outputFullScale;
    const double d = plan.amplitude / 100 * full;
    if (u0 + d > full || u0 - d < 0) {
        fail(tr("the operating speed needs %1 % output: no room for ±%2 % around it")
                 .arg(u0 * 100 / full, 0, 'f', 1)
                 .arg(plan.amplitude));
        return;
    }
    emit phase(tr("Relay test around %1 %2 (output %3 % ± %4 %)")
                   .arg(plan.speed)
                   .arg(ctx->result.speedUnit)
                   .arg(u0 * 100 / full, 0, 'f', 1)
                   .arg(plan.amplitude));
    ctx->result.samples.clear();
    ctx->t0 = nowMs();
    ctx->polls = 0;
    ctx->high = high;
    const double h = plan.hysteresis > 0 ? plan.hysteresis : 0.01 * plan.speed;
    ctx->loop = [this, ctx, plan, u0, d, h] {
        poll([this, ctx, plan, u0, d, h](const TuningSample& sample) {
            TuningSample s = sample;
            s.command = (ctx->high ? u0 + d : u0 - d) * ctx->openScale;
            ctx->result.samples << s;
            emit sampled(s);
            const double e = plan.speed - s.speed;
            const bool next = e > h ? true : e < -h ? false : ctx->high;
            const int n = ctx->result.samples.size();
            const bool upCrossing =
                n > 1 && ctx->result.samples[n - 2].speed < plan.speed && s.speed >= plan.speed;
            if (upCrossing) {
                const RelayAnalysis a =
                    RelayAnalysis::analyse(ctx->result.samples, plan.speed, d, h, plan.cycles);
                if (a.steady || a.busPaced) { // the rest of its checks: relayConclude
                    ctx->result.relay = a;
                    relayConclude(plan, d);
                    return;
                }
            }
            if (s.tMs > plan.maxMs) {
                const RelayAnalysis a =
                    RelayAnalysis::analyse(ctx->result.samples, plan.speed, d, h, plan.cycles);
                ctx->result.relay = a;
                ctx->result.advice = a.advice;
                fail(tr("no steady oscillation within %1 s: %2")
                         .arg(plan.maxMs / 1000.0)
                         .arg(a.error.isEmpty() ? tr("try a larger amplitude") : a.error));
                return;
            }
            if (next == ctx->high) {
                ctx->loop();
                return;
            }
            ctx->high = next;
            command((next ? u0 + d : u0 - d) * ctx->openScale, [ctx] { ctx->loop(); });
        });
    };
    command((high ? u0 + d : u0 - d) * ctx->openScale, [ctx] { ctx->loop(); });
}

void TuningRunner::relayConclude(const RelayPlan& plan, double d)
{
    const auto ctx = m_ctx;
    RelayTuning::Input in;
    in.relay = ctx->result.relay;
    in.plantGain = ctx->plantGain;
    in.closedScale = ctx->closedScale;
    in.openScale = ctx->openScale;
    in.d = d;
    in.restCurrent = ctx->restCurrent;
    in.currentLimit = ctx->currentLimit;
    in.speed = plan.speed;
    in.rule = plan.rule;
    RelayTuning::conclude(m_spec, in, &ctx->result);
    const Result& r = ctx->result;
    qCDebug(lcModel) << "autotune: Ku" << r.relay.ultimateGain << "Tu" << r.relay.periodMs
                     << "readings/period" << r.relay.readingsPerPeriod << "bus delay"
                     << r.busDelayMs << "model tau" << r.plant.tauMs << "dead" << r.plant.deadMs
                     << "A per output" << r.plant.currentPerOutput << "own Ku" << r.ultimateGain
                     << "Tu" << r.ultimatePeriodMs << "proposal" << r.proposal.toString()
                     << r.error;
    if (!r.ok) {
        fail(tr("the relay result was refused: %1").arg(r.error));
        return;
    }
    finish();
}

} // namespace opentop
