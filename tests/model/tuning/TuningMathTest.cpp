// The tuning calculations on responses whose figures are known in closed form.
#include "model/profile/ProfileRegistry.h"
#include "model/tuning/GainDesign.h"
#include "model/tuning/PlantModel.h"
#include "model/tuning/RelayAnalysis.h"
#include "model/tuning/StepMetrics.h"
#include "model/tuning/TuningRules.h"
#include "model/tuning/TuningSpec.h"
#include "model/tuning/TuningVerdict.h"

#include <QJsonArray>
#include <QJsonObject>
#include <gtest/gtest.h>

#include <cmath>

using namespace opentop;

namespace {

// A first-order step 100 → 600 with τ = 40 ms, sampled every millisecond from t = 0.
TuningSamples firstOrder(double tau = 40, double from = 100, double to = 600)
{
    TuningSamples s;
    for (int t = -20; t <= 1000; ++t) {
        const double y = t < 0 ? from : to + (from - to) * std::exp(-t / tau);
        s.append({double(t), to, y, 2.0 + (t == 3 ? 1.5 : 0), 0});
    }
    return s;
}

// A second-order step 0 → 1 with damping ζ and natural frequency ωn (rad/ms).
double secondOrder(double t, double zeta, double wn)
{
    const double wd = wn * std::sqrt(1 - zeta * zeta);
    return 1 - std::exp(-zeta * wn * t) *
                   (std::cos(wd * t) + zeta / std::sqrt(1 - zeta * zeta) * std::sin(wd * t));
}

} // namespace

TEST(StepMetrics, FirstOrderResponse)
{
    const StepMetrics m = StepMetrics::measure(firstOrder(), 100, 600);
    ASSERT_TRUE(m.valid) << qPrintable(m.error);
    ASSERT_TRUE(m.riseMs);
    EXPECT_NEAR(*m.riseMs, 40 * std::log(9.0), 0.05); // 10–90 %: τ·ln 9, interpolated
    EXPECT_DOUBLE_EQ(m.overshootPercent, 0);
    ASSERT_TRUE(m.settlingMs);
    EXPECT_NEAR(*m.settlingMs, 40 * std::log(50.0), 1.0); // into ±2 %: τ·ln 50
    EXPECT_NEAR(m.steadyStateError, 0, 0.01);
    EXPECT_DOUBLE_EQ(m.peakCurrent, 3.5);
}

TEST(StepMetrics, SecondOrderOvershootAndDownwardSteps)
{
    const double zeta = 0.5, wn = 0.05;
    TuningSamples s;
    for (int t = 0; t <= 1000; ++t)
        s.append({double(t), 500, 200 + 300 * secondOrder(t, zeta, wn), 0, 0});
    const StepMetrics m = StepMetrics::measure(s, 200, 500);
    ASSERT_TRUE(m.valid);
    const double expected = 100 * std::exp(-M_PI * zeta / std::sqrt(1 - zeta * zeta)); // 16.3 %
    EXPECT_NEAR(m.overshootPercent, expected, 0.1);
    // Downwards the same response mirrored gives the same figures.
    TuningSamples down = s;
    for (TuningSample& x : down)
        x.speed = 700 - x.speed;
    const StepMetrics d = StepMetrics::measure(down, 500, 200);
    EXPECT_NEAR(d.overshootPercent, m.overshootPercent, 1e-9);
    ASSERT_TRUE(d.riseMs && m.riseMs);
    EXPECT_NEAR(*d.riseMs, *m.riseMs, 1e-9);
    EXPECT_EQ(d.settlingMs, m.settlingMs);
}

TEST(StepMetrics, NotSettledAndSteadyStateError)
{
    TuningSamples s;
    for (int t = 0; t <= 500; ++t) // oscillating ±10 % around 450 instead of 500
        s.append({double(t), 500, 450 + 50 * std::sin(t / 20.0), 0, 0});
    const StepMetrics m = StepMetrics::measure(s, 0, 500);
    ASSERT_TRUE(m.valid);
    EXPECT_FALSE(m.settlingMs);
    EXPECT_NEAR(m.steadyStateError, -50, 15);
    EXPECT_FALSE(StepMetrics::measure(s, 500, 500).valid);
    // Already beyond 10 % at the step (the speed never settled at `from`): no rise time.
    EXPECT_FALSE(StepMetrics::measure(firstOrder(40, 100, 600), -500, 600).riseMs);
    EXPECT_FALSE(StepMetrics::measure({}, 0, 500).valid);
}

TEST(StepMetrics, ASwingThroughTheBandAsTheRecordEndsIsNotSettled)
{
    // ±15 % around 500 with a 400 ms period, read every 50 ms (a loaded bus) and then twice
    // within 2 ms as the record ends, both inside ±2 %: the swing is passing, not settled.
    TuningSamples s;
    const auto y = [](double t) { return 500 + 75 * std::sin(2 * M_PI * t / 400); };
    for (int t = 0; t <= 1150; t += 50)
        s.append({double(t), 500, y(t), 0, 0});
    s.append({1199.0, 500, 503.0, 0, 0});
    s.append({1200.5, 500, 501.0, 0, 0});
    const StepMetrics m = StepMetrics::measure(s, 0, 500);
    ASSERT_TRUE(m.valid);
    EXPECT_FALSE(m.settlingMs) << "settled at " << *m.settlingMs << " ms";
    // The same readings continuing in the band for a fifth of the record: settled.
    for (int t = 1250; t <= 1500; t += 50)
        s.append({double(t), 500, 500.5, 0, 0});
    const StepMetrics later = StepMetrics::measure(s, 0, 500);
    ASSERT_TRUE(later.settlingMs);
    EXPECT_DOUBLE_EQ(*later.settlingMs, 1199.0);
}

TEST(RelayAnalysis, UltimateGainAndPeriodOfASteadyOscillation)
{
    TuningSamples s;
    const double a = 40, period = 50, d = 100;
    for (int t = 0; t < 600; t += 2)
        s.append({double(t), 0, 500 + a * std::sin(2 * M_PI * t / period), 0, 0});
    const RelayAnalysis r = RelayAnalysis::analyse(s, 500, d, 0, 3);
    ASSERT_TRUE(r.ok) << qPrintable(r.error);
    EXPECT_NEAR(r.periodMs, period, 0.5);
    EXPECT_NEAR(r.amplitude, a, 0.5);
    EXPECT_NEAR(r.ultimateGain, 4 * d / (M_PI * a), 0.05);
    // With hysteresis ε: 4d / (π √(a² − ε²)).
    const RelayAnalysis h = RelayAnalysis::analyse(s, 500, d, 10, 3);
    EXPECT_NEAR(h.ultimateGain, 4 * d / (M_PI * std::sqrt(a * a - 100)), 0.05);
    // Too short: fewer cycles than asked.
    EXPECT_FALSE(RelayAnalysis::analyse(s.mid(0, 60), 500, d, 0, 3).ok);
}

// `perPeriod` readings per period of a relay oscillation ±a around 500: above the set point for
// `above` of each period.
TuningSamples relayWave(double perPeriod, double above = 0.5, double a = 40, double period = 60,
                        int cycles = 8)
{
    TuningSamples s;
    const double dt = period / perPeriod;
    for (double t = 0; t < cycles * period; t += dt) {
        const double phase = std::fmod(t, period) / period;
        const double y = phase < above ? a * std::sin(M_PI * phase / above)
                                       : -a * std::sin(M_PI * (phase - above) / (1 - above));
        s.append({t, 0, 500 + y, 0, 0});
    }
    return s;
}

TEST(RelayAnalysis, TooFewReadingsPerPeriodShowTheBusAndAreRefused)
{
    const RelayAnalysis few = RelayAnalysis::analyse(relayWave(4.3), 500, 100, 0, 3);
    EXPECT_TRUE(few.busPaced); // the relay need not wait for steadier cycles
    EXPECT_FALSE(few.steady);
    EXPECT_FALSE(few.ok);
    EXPECT_NEAR(few.readingsPerPeriod, 4.3, 0.2);
    EXPECT_NEAR(few.readingMs, 60 / 4.3, 0.5);
    EXPECT_TRUE(few.error.contains(QStringLiteral("readings"))) << qPrintable(few.error);
    EXPECT_TRUE(few.advice.contains(QStringLiteral("line rate"))) << qPrintable(few.advice);
    const RelayAnalysis enough = RelayAnalysis::analyse(relayWave(12), 500, 100, 0, 3);
    EXPECT_TRUE(enough.ok) << qPrintable(enough.error);
    EXPECT_NEAR(enough.asymmetry, 0, 0.05);
}

TEST(RelayAnalysis, LopsidedOrUnsteadyCyclesAreRefused)
{
    const RelayAnalysis lopsided = RelayAnalysis::analyse(relayWave(30, 0.72), 500, 100, 0, 3);
    EXPECT_TRUE(lopsided.steady);
    EXPECT_FALSE(lopsided.ok);
    EXPECT_NEAR(lopsided.asymmetry, 0.44, 0.05);
    EXPECT_TRUE(lopsided.error.contains(QStringLiteral("lopsided"))) << qPrintable(lopsided.error);
    EXPECT_FALSE(lopsided.advice.isEmpty());
    EXPECT_TRUE(RelayAnalysis::analyse(relayWave(30, 0.6), 500, 100, 0, 3).ok);
    // Every other cycle a third smaller: amplitudes differ by 20 % of their mean.
    TuningSamples uneven = relayWave(30);
    for (TuningSample& x : uneven) {
        if (int(x.tMs / 60) % 2)
            x.speed = 500 + (x.speed - 500) * 0.62;
    }
    const RelayAnalysis u = RelayAnalysis::analyse(uneven, 500, 100, 0, 3);
    EXPECT_FALSE(u.steady);
    EXPECT_FALSE(u.ok);
    EXPECT_GT(u.amplitudeSpread, RelayAnalysis::kMaxAmplitudeSpread);
    EXPECT_TRUE(u.error.contains(QStringLiteral("not steady"))) << qPrintable(u.error);
    EXPECT_TRUE(u.advice.contains(QStringLiteral("amplitude"))) << qPrintable(u.advice);
}

TEST(TuningRules, ClassicZieglerNicholsInTheControllersForm)
{
    TuningSpec spec;
    spec.periodMs = 1;
    const PidGains g = TuningRules::propose(TuningRules::Rule::Stiff, 5, 50, spec, 10);
    EXPECT_DOUBLE_EQ(g.p, 3);               // 0.6 Ku
    EXPECT_DOUBLE_EQ(g.i, 3.0 * 1 / 25);    // Kp·T/Ti, Ti = Tu/2
    EXPECT_DOUBLE_EQ(g.d, 3.0 * 6.25 / 10); // Kp·Td/N, Td = Tu/8
    EXPECT_EQ(g.dPeriodMs, 10);
    const PidGains pi = TuningRules::propose(TuningRules::Rule::ZieglerNicholsPi, 5, 50, spec, 10);
    EXPECT_DOUBLE_EQ(pi.d, 0);
    EXPECT_LT(TuningRules::propose(TuningRules::Rule::Soft, 5, 50, spec, 10).p, g.p);
    for (const QString& id : TuningRules::ids())
        EXPECT_EQ(TuningRules::id(*TuningRules::fromId(id)), id);
    EXPECT_FALSE(TuningRules::fromId(QStringLiteral("fast")));
}

TEST(PlantModel, RelayFitRoundTripsAndLeavesOutTheBusDelay)
{
    const PlantModel m = PlantModel::fromRelay(1.0, 4, 60, 0, 1);
    ASSERT_TRUE(m.valid) << qPrintable(m.error);
    double ku = 0, tu = 0;
    ASSERT_TRUE(m.ultimate(&ku, &tu));
    EXPECT_NEAR(ku, 4, 1e-6);
    EXPECT_NEAR(tu, 60, 1e-6);
    // The same experiment with 8 ms of it on the bus: the drive's own loop is stiffer.
    const PlantModel own = PlantModel::fromRelay(1.0, 4, 60, 8, 1);
    EXPECT_DOUBLE_EQ(own.tauMs, m.tauMs);
    EXPECT_NEAR(own.deadMs, m.deadMs - 8, 1e-9);
    ASSERT_TRUE(own.ultimate(&ku, &tu));
    EXPECT_GT(ku, 4);
    EXPECT_LT(tu, 60);
    EXPECT_FALSE(PlantModel::fromRelay(0.2, 4, 60, 0, 1).valid); // K·Ku ≤ 1
}

TEST(PlantModel, PredictedStepSettlesWithProposedGainsAndOscillatesBeyondKu)
{
    const PlantModel m = PlantModel::fromRelay(1.0, 4, 60, 0, 1);
    TuningSpec spec;
    spec.periodMs = 1;
    spec.outputFullScale = 1000;
    double ku = 0, tu = 0;
    ASSERT_TRUE(m.ultimate(&ku, &tu));
    const PidGains good = TuningRules::propose(TuningRules::Rule::Medium, ku, tu, spec, 5);
    const StepMetrics settled =
        StepMetrics::measure(m.simulateStep(good, spec, 200, 400, 1500, 1), 200, 400);
    ASSERT_TRUE(settled.settlingMs);
    EXPECT_LT(settled.overshootPercent, 30);
    PidGains high;
    high.p = ku * 1.5;
    const StepMetrics unstable =
        StepMetrics::measure(m.simulateStep(high, spec, 200, 400, 1500, 1), 200, 400);
    EXPECT_FALSE(unstable.settlingMs);
}

TEST(TuningSpec, TheDcControllerCanBeTunedTheDbuCannot)
{
    QString error;
    const Profile* dc = ProfileRegistry::builtIn().family(QStringLiteral("dcpid"));
    ASSERT_TRUE(dc);
    const std::optional<TuningSpec> spec = TuningSpec::of(*dc, &error);
    ASSERT_TRUE(spec) << qPrintable(error);
    EXPECT_EQ(spec->gainP, QStringLiteral("pid.p"));
    EXPECT_EQ(spec->openLoopMode, 0);
    ASSERT_TRUE(spec->closedLoop(2));
    EXPECT_EQ(spec->closedLoop(2)->feedback, QStringLiteral("status.commutation"));
    EXPECT_FALSE(spec->closedLoop(0));
    const Profile* dbu = ProfileRegistry::builtIn().family(QStringLiteral("dbu"));
    EXPECT_FALSE(TuningSpec::of(*dbu, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("no speed loop"))) << qPrintable(error);
    // A section that names an unknown feedback is refused with what it needs.
    Profile broken = *dc;
    broken.tuning.insert(
        QStringLiteral("closedLoopModes"),
        QJsonArray{QJsonObject{{QStringLiteral("mode"), 2},
                               {QStringLiteral("feedback"), QStringLiteral("status.nothing")}}});
    EXPECT_FALSE(TuningSpec::of(broken, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("closedLoopModes"))) << qPrintable(error);
}

namespace {

// The simulator's motor with its defaults, as a model: K 1, τ 40 ms, θ 12 ms; 0.048 A per output
// count (24 V, 0.5 Ω, full scale 1000), 0.5 A at rest, a 10 A limit.
PlantModel currentLimitedMotor(double tau = 40)
{
    PlantModel m;
    m.valid = true;
    m.gain = 1;
    m.tauMs = tau;
    m.deadMs = 12;
    m.currentPerOutput = 0.048;
    m.restCurrent = 0.5;
    m.currentLimit = 10;
    return m;
}

TuningSpec controllerSpec()
{
    TuningSpec spec;
    spec.periodMs = 1;
    spec.outputFullScale = 1000;
    return spec;
}

} // namespace

TEST(PlantModel, TheCurrentLimitSlowsTheRiseAndTheIntegralWindsUp)
{
    const TuningSpec spec = controllerSpec();
    PlantModel limited = currentLimitedMotor(160); // a heavy load: the limit holds for long
    PlantModel linear = limited;
    linear.currentLimit = 0;
    PidGains g;
    g.p = 3;
    g.i = 0.05;
    const StepMetrics free =
        StepMetrics::measure(linear.simulateStep(g, spec, 150, 300, 1500, 1), 150, 300);
    const TuningSamples s = limited.simulateStep(g, spec, 150, 300, 1500, 1);
    const StepMetrics held = StepMetrics::measure(s, 150, 300);
    ASSERT_TRUE(free.riseMs && held.riseMs);
    EXPECT_GT(*held.riseMs, *free.riseMs * 1.5);
    EXPECT_GT(held.overshootPercent, free.overshootPercent + 10);
    EXPECT_NEAR(held.peakCurrent, 10, 0.01); // the model's current stops at the limit
}

TEST(PlantModel, CurrentPerOutputFromTheRelaysSwitches)
{
    // A relay 400 ± 100 counts on K 1, τ 40 ms, c 0.048 A per count, 0.5 A at rest. Each reading
    // takes 5 ms (the value is as old when it arrives); a switch's write takes effect as the
    // reading that asks for it arrives, and the next reading starts 10 ms later.
    const double c = 0.048, d = 100, tau = 40;
    TuningSamples s;
    double x = 400, u = 500, next = 0, switchAt = -1, wanted = 500;
    QVector<double> seen(25, 400); // the drive's speed measurement: 12.5 ms behind the shaft
    for (double now = 0; now < 1500; now += 0.5) {
        if (switchAt >= 0 && now >= switchAt) {
            u = wanted;
            switchAt = -1;
        }
        x += (u - x) * 0.5 / tau;
        seen.removeFirst();
        seen.append(x);
        if (now < next)
            continue;
        s.append({now + 5, u / 10, seen.first(), std::abs(0.5 + c * (u - x)), 0});
        wanted = seen.first() < 400 ? 500 : 300;
        if (wanted != u) {
            switchAt = now + 5;
            next = now + 15;
        } else {
            next = now + 5;
        }
    }
    EXPECT_NEAR(PlantModel::currentPerOutputOf(s, 0.1, d, tau), c, 0.25 * c);
    EXPECT_EQ(PlantModel::currentPerOutputOf({}, 0.1, d, tau), 0);
}

TEST(GainDesign, TheRulesGainsAreLoweredUntilTheModelKeepsTheRulesPromise)
{
    const TuningSpec spec = controllerSpec();
    const PlantModel m = currentLimitedMotor(160);
    double ku = 0, tu = 0;
    ASSERT_TRUE(m.ultimate(&ku, &tu));
    // Ziegler–Nichols "some overshoot" as it stands overshoots beyond its bound here.
    const PidGains plain = TuningRules::propose(TuningRules::Rule::Medium, ku, tu, spec, 10);
    const StepMetrics plainStep =
        StepMetrics::measure(m.simulateStep(plain, spec, 150, 300, 1500, 5), 150, 300);
    EXPECT_GT(plainStep.overshootPercent, TuningRules::overshootBound(TuningRules::Rule::Medium));
    const GainDesign d = GainDesign::choose(m, TuningRules::Rule::Medium, spec, 10, 150, 300, 8);
    ASSERT_TRUE(d.ok) << qPrintable(d.error);
    EXPECT_TRUE(d.kpScale < 1 || d.tiScale > 1);
    EXPECT_LE(d.metrics.overshootPercent, TuningRules::overshootBound(TuningRules::Rule::Medium));
    ASSERT_TRUE(d.metrics.settlingMs);
    EXPECT_LE(*d.metrics.settlingMs, GainDesign::kRecordMs * 2 / 3);
    EXPECT_NEAR(d.ultimateGain, ku, 1e-9);
    // Soft keeps its promise of no overshoot worth the name.
    const GainDesign soft = GainDesign::choose(m, TuningRules::Rule::Soft, spec, 10, 150, 300, 8);
    ASSERT_TRUE(soft.ok) << qPrintable(soft.error);
    EXPECT_LE(soft.metrics.overshootPercent, 2);
    // A model with no ultimate point has nothing to offer.
    EXPECT_FALSE(
        GainDesign::choose(PlantModel(), TuningRules::Rule::Medium, spec, 10, 150, 300, 8).ok);
}

namespace {

TuningRunner::Result measuredStep(const TuningSamples& samples, double from, double to)
{
    TuningRunner::Result r;
    r.ok = true;
    r.from = from;
    r.to = to;
    r.samples = samples;
    r.metrics = StepMetrics::measure(samples, from, to);
    return r;
}

} // namespace

TEST(TuningVerdict, NotSettlingOrOvershootingFarBeyondThePredictionFails)
{
    StepMetrics predicted;
    predicted.valid = true;
    predicted.overshootPercent = 16.3;
    predicted.settlingMs = 160;
    // As predicted: ζ = 0.5, 16 % overshoot, settled.
    TuningSamples asPredicted;
    for (int t = 0; t <= 1500; ++t)
        asPredicted.append({double(t), 500, 200 + 300 * secondOrder(t, 0.5, 0.05), 1, 0});
    const TuningVerdict good = TuningVerdict::judge(measuredStep(asPredicted, 200, 500), predicted);
    EXPECT_TRUE(good.passed) << qPrintable(good.text());
    EXPECT_TRUE(good.measured);
    // ζ = 0.25: 44 % overshoot, more than 10 points beyond the prediction.
    TuningSamples ringing;
    for (int t = 0; t <= 1500; ++t)
        ringing.append({double(t), 500, 200 + 300 * secondOrder(t, 0.25, 0.05), 1, 0});
    const TuningVerdict far = TuningVerdict::judge(measuredStep(ringing, 200, 500), predicted);
    EXPECT_FALSE(far.passed);
    EXPECT_TRUE(far.text().contains(QStringLiteral("44."))) << qPrintable(far.text());
    EXPECT_TRUE(far.text().contains(QStringLiteral("16.3"))) << qPrintable(far.text());
    // Oscillating to the end: never settles.
    TuningSamples oscillating;
    for (int t = 0; t <= 1500; ++t)
        oscillating.append({double(t), 500, 500 - 300 * std::cos(t / 20.0) * 0.3, 1, 0});
    const TuningVerdict never =
        TuningVerdict::judge(measuredStep(oscillating, 200, 500), predicted);
    EXPECT_FALSE(never.passed);
    EXPECT_TRUE(never.text().contains(QStringLiteral("did not settle")))
        << qPrintable(never.text());
    // Stopped by a limit: not measured to its end.
    TuningRunner::Result stopped = measuredStep(ringing.mid(0, 100), 200, 500);
    stopped.ok = false;
    stopped.aborted = true;
    stopped.error = QStringLiteral("speed 620 1/s beyond the test's limit 600 1/s");
    const TuningVerdict limit = TuningVerdict::judge(stopped, predicted);
    EXPECT_FALSE(limit.passed);
    EXPECT_FALSE(limit.measured);
    EXPECT_TRUE(limit.text().contains(QStringLiteral("beyond the test's limit")))
        << qPrintable(limit.text());
}
