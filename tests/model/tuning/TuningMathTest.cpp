// The tuning calculations on responses whose figures are known in closed form.
#include "profile/ProfileRegistry.h"
#include "tuning/PlantModel.h"
#include "tuning/RelayAnalysis.h"
#include "tuning/StepMetrics.h"
#include "tuning/TuningRules.h"
#include "tuning/TuningSpec.h"

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
