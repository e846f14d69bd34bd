// The relay autotune's method on the simulator's plant, across its range (inertia, gain, the
// speed gate's dead time, load, current limit) and line rates 9600/19200/115200, on a virtual
// line (VirtualLine.h: the in-process simulator, time moved by the frames' wire time): a relay
// the bus cannot resolve is refused with what to change; gains that are offered settle on the
// plant as predicted, checked by the step after Accept; unsteady and lopsided relays, and a
// step that does not settle, are named. OPENTOP_TUNING_TABLE=1 prints each case's figures
// and those of the method before this check (docs/tuning.md's table).
#include "model/tuning/TuningRunner.h"
#include "model/tuning/TuningVerdict.h"

#include "model/profile/ProfileRegistry.h"
#include "model/session/DeviceSession.h"
#include "tests/model/DriveSimFixture.h"
#include "tests/model/tuning/VirtualLine.h"

#include <QEventLoop>
#include <QTimer>
#include <gtest/gtest.h>

#include <cstdio>

using namespace opentop;
using namespace opentop::test;

namespace {

struct Case
{
    const char* motor; // DcMotor::Model keys, "" for the default motor
    int baud;
    char parity;
    double speed; // 1/s
    TuningRules::Rule rule;
    const char* refusal;   // nullptr: gains must be offered; else a word of the reason
    int maxCurrent = 1000; // config.max_current, 0.01 A
    double amplitude = 10; // % of full output
    int otherEvery = 0;    // VirtualLineBackend::otherEvery
};

struct Outcome
{
    TuningRunner::Result tune;
    TuningRunner::Result check;
    TuningVerdict verdict;
    // The method before the checks: the rule on the model's ultimate point, no current limit.
    PidGains oldGains;
    StepMetrics oldPredicted;
    TuningRunner::Result oldCheck;
};

class TuningMethodTest : public DriveSimFixture
{
protected:
    void open(const Case& c)
    {
        ASSERT_TRUE(line.open(QStringLiteral("dcpid@7"), c.baud, c.parity));
        line.backend->otherEvery = c.otherEvery;
        control({QStringLiteral("set"), QStringLiteral("0x0080"), QStringLiteral("2")});
        control({QStringLiteral("set"), QStringLiteral("0x0087"), QString::number(c.maxCurrent)});
        if (*c.motor)
            control(QStringList{QStringLiteral("motor")} +
                    QString::fromLatin1(c.motor).split(QLatin1Char(',')));
        const Profile* profile = ProfileRegistry::builtIn().family(QStringLiteral("dcpid"));
        session = std::make_unique<DeviceSession>(line.client.get(), *profile, 7, QString());
        QString error;
        spec = *TuningSpec::of(*profile, &error);
        runner = std::make_unique<TuningRunner>(session.get(), spec);
        runner->setClock(line.time());
        TuningRunner::Limits limits;
        limits.maxSpeed = 1.6 * c.speed;
        limits.maxCurrent = 1.2 * c.maxCurrent / 100;
        runner->setLimits(limits);
    }
    void TearDown() override
    {
        runner.reset();
        session.reset();
        line.client.reset();
        DriveSimFixture::TearDown();
    }
    void control(const QStringList& args)
    {
        const SimControlResult r = line.bus->control(7, args);
        ASSERT_TRUE(r.ok) << qPrintable(r.text);
    }
    TuningRunner::Result autotune(const Case& c)
    {
        TuningRunner::RelayPlan plan;
        plan.speed = c.speed;
        plan.amplitude = c.amplitude;
        plan.rule = c.rule;
        return await<TuningRunner::Result>([&](auto done) { runner->startAutotune(plan, done); });
    }
    bool write(const PidGains& g)
    {
        return await<bool>([&](auto done) {
            runner->writeGains(g, [done](bool ok, const PidGains&, const QString&) { done(ok); });
        });
    }
    TuningRunner::Result step(double from, double to)
    {
        TuningRunner::StepPlan plan;
        plan.from = from;
        plan.to = to;
        plan.recordMs = int(GainDesign::kRecordMs);
        return await<TuningRunner::Result>([&](auto done) { runner->startStep(plan, done); });
    }
    // Autotune, and with a proposal: Accept (write it) and the check step half → full speed.
    Outcome tuneAndCheck(const Case& c)
    {
        Outcome run;
        run.tune = autotune(c);
        if (run.tune.ok) {
            EXPECT_TRUE(write(run.tune.proposal));
            run.check = step(c.speed / 2, c.speed);
            run.verdict = TuningVerdict::judge(run.check, run.tune.predictedMetrics);
        }
        if (qEnvironmentVariableIsSet("OPENTOP_TUNING_TABLE") &&
            (run.tune.relay.steady || run.tune.relay.busPaced))
            oldMethod(c, &run);
        return run;
    }
    // What the method proposed and predicted before this issue, from the same relay.
    void oldMethod(const Case& c, Outcome* run)
    {
        const TuningRunner::Result& t = run->tune;
        const double busDelay = t.busDelayMs > 0 ? t.busDelayMs : t.relay.readingMs;
        PlantModel m = PlantModel::fromRelay(t.plantGain, t.relay.ultimateGain, t.relay.periodMs,
                                             busDelay, spec.periodMs);
        double ku = t.relay.ultimateGain, tu = t.relay.periodMs;
        if (m.valid)
            m.ultimate(&ku, &tu);
        run->oldGains = TuningRules::propose(c.rule, ku, tu, spec, 10);
        run->oldPredicted =
            StepMetrics::measure(m.simulateStep(run->oldGains, spec, c.speed / 2, c.speed, 1500, 5),
                                 c.speed / 2, c.speed);
        EXPECT_TRUE(write(run->oldGains));
        run->oldCheck = step(c.speed / 2, c.speed);
    }

    VirtualLine line;
    std::unique_ptr<DeviceSession> session;
    TuningSpec spec;
    std::unique_ptr<TuningRunner> runner;
};

QString settle(const std::optional<double>& ms)
{
    return ms ? QString::number(*ms, 'f', 0) : QStringLiteral("never");
}

void print(const Case& c, const Outcome& r)
{
    if (!qEnvironmentVariableIsSet("OPENTOP_TUNING_TABLE"))
        return;
    const StepMetrics& om = r.oldCheck.metrics;
    const QString plant =
        QString::fromLatin1(*c.motor ? c.motor : "default") +
        (c.maxCurrent != 1000 ? QStringLiteral(", %1 A limit").arg(c.maxCurrent / 100)
                              : QString()) +
        (c.amplitude != 10 ? QStringLiteral(", relay %1 %").arg(c.amplitude) : QString());
    const QString bus = QStringLiteral("%1 %2%3")
                            .arg(c.baud)
                            .arg(QLatin1Char(c.parity))
                            .arg(c.otherEvery == 1   ? QStringLiteral(", other drive every reading")
                                 : c.otherEvery == 2 ? QStringLiteral(", other drive")
                                                     : QString());
    std::printf(
        "| %s | %s | %s | Tu %.0f ms, %.1f readings | %s | %s | %s |\n", qPrintable(plant),
        qPrintable(bus), qPrintable(TuningRules::id(c.rule)), r.tune.relay.periodMs,
        r.tune.relay.readingsPerPeriod,
        qPrintable(
            r.oldCheck.samples.isEmpty()
                ? QStringLiteral("–")
                : QStringLiteral("P %1: predicted %2 % / %3 ms, measured %4 % / %5 ms")
                      .arg(r.oldGains.p, 0, 'f', 2)
                      .arg(r.oldPredicted.overshootPercent, 0, 'f', 1)
                      .arg(settle(r.oldPredicted.settlingMs))
                      .arg(om.overshootPercent, 0, 'f', 1)
                      .arg(r.oldCheck.ok ? settle(om.settlingMs) : r.oldCheck.error.left(40))),
        qPrintable(r.tune.ok ? QStringLiteral("P %1: predicted %2 % / %3 ms, measured "
                                              "%4 % / %5 ms")
                                   .arg(r.tune.proposal.p, 0, 'f', 2)
                                   .arg(r.tune.predictedMetrics.overshootPercent, 0, 'f', 1)
                                   .arg(settle(r.tune.predictedMetrics.settlingMs))
                                   .arg(r.verdict.overshootPercent, 0, 'f', 1)
                                   .arg(settle(r.verdict.settlingMs))
                             : QStringLiteral("refused: ") + r.tune.error.left(90)),
        r.tune.ok ? (r.verdict.passed ? "passed" : "FAILED") : "–");
    std::fflush(stdout);
}

void expectCase(const Case& c, const Outcome& r)
{
    const std::string name = std::string(*c.motor ? c.motor : "default") + " at " +
                             std::to_string(c.baud) + " " + qPrintable(TuningRules::id(c.rule));
    if (c.refusal) {
        EXPECT_FALSE(r.tune.ok) << name << ": " << qPrintable(r.tune.proposal.toString());
        EXPECT_TRUE(r.tune.error.contains(QLatin1String(c.refusal)))
            << name << ": " << qPrintable(r.tune.error);
        EXPECT_FALSE(r.tune.advice.isEmpty()) << name;
        EXPECT_TRUE(r.tune.stopConfirmed) << name;
        return;
    }
    ASSERT_TRUE(r.tune.ok) << name << ": " << qPrintable(r.tune.error);
    EXPECT_TRUE(r.verdict.passed) << name << ": " << qPrintable(r.verdict.text());
    ASSERT_TRUE(r.check.metrics.settlingMs) << name;
    EXPECT_LE(r.check.metrics.overshootPercent, TuningRules::overshootBound(c.rule) + 10) << name;
    EXPECT_TRUE(r.check.stopConfirmed) << name;
}

} // namespace

// The plant's range on a line fast enough for it: every rule's gains settle as predicted.
TEST_F(TuningMethodTest, OfferedGainsSettleOnThePlantAsPredicted)
{
    using R = TuningRules::Rule;
    const Case cases[] = {
        {"", 115200, 'N', 300, R::Medium, nullptr},
        {"", 115200, 'N', 300, R::Soft, nullptr},
        {"", 115200, 'N', 300, R::Stiff, nullptr},
        {"", 115200, 'N', 300, R::TyreusLuyben, nullptr},
        {"", 115200, 'N', 300, R::ZieglerNicholsPi, nullptr},
        {"inertia=4e-4", 115200, 'N', 300, R::Medium, nullptr},
        {"inertia=4e-4", 115200, 'N', 300, R::Soft, nullptr},
        {"inertia=1e-3", 115200, 'N', 300, R::Medium, nullptr},
        {"inertia=3e-5", 115200, 'N', 300, R::Medium, nullptr},
        {"gate=50", 115200, 'N', 300, R::Medium, nullptr},
        {"load=0.1", 115200, 'N', 300, R::Medium, nullptr},
        {"supply=12", 115200, 'N', 200, R::Medium, nullptr},
        {"no_load=2000", 115200, 'N', 600, R::Medium, nullptr, 1000, 5},
        {"", 115200, 'N', 300, R::Medium, nullptr, 500},         // a 5 A current limit
        {"", 115200, 'N', 300, R::Medium, nullptr, 1000, 10, 2}, // another drive polled too
        {"", 38400, 'N', 300, R::Medium, nullptr},
        {"", 19200, 'N', 300, R::Medium, nullptr}, // nothing else on the line
        {"gate=100", 19200, 'N', 300, R::Medium, nullptr, 1000, 10, 2},
        {"inertia=1e-3", 9600, 'E', 300, R::Medium, nullptr},
        {"gate=100", 9600, 'E', 300, R::Soft, nullptr},
    };
    for (const Case& c : cases) {
        TearDown();
        open(c);
        const Outcome r = tuneAndCheck(c);
        print(c, r);
        expectCase(c, r);
    }
}

// The line too slow for the motor: the relay's period holds too few readings (the case:
// 19200 bit/s with other drives polled, 300 1/s, 10 %), or the drive's own loop would be faster
// than the bus can watch.
TEST_F(TuningMethodTest, ARelayTheBusCannotResolveIsRefusedWithWhatToChange)
{
    using R = TuningRules::Rule;
    const Case cases[] = {
        // The case: another drive polled between the tuning's readings.
        {"", 19200, 'N', 300, R::Medium, "readings", 1000, 10, 2},
        {"", 19200, 'N', 300, R::Soft, "readings", 1000, 10, 1},
        {"", 9600, 'E', 300, R::Medium, "readings"},
        {"inertia=3e-5", 19200, 'N', 300, R::Medium, "readings"},
        {"gate=10", 19200, 'N', 300, R::Medium, "readings"},
        {"inertia=1e-5,gate=10", 115200, 'N', 300, R::Medium, "readings"},
        // The relay is resolved, but the drive's own loop would be faster than the bus can watch.
        {"inertia=1e-3", 19200, 'N', 300, R::Medium, "own loop", 1000, 10, 2},
    };
    for (const Case& c : cases) {
        TearDown();
        open(c);
        const Outcome r = tuneAndCheck(c);
        print(c, r);
        expectCase(c, r);
        EXPECT_TRUE(r.tune.advice.contains(QStringLiteral("line rate")))
            << qPrintable(r.tune.advice);
        EXPECT_EQ(line.bus->control(7, {QStringLiteral("get"), QStringLiteral("0x0080")})
                      .text.contains(QStringLiteral("= 2 ")),
                  true); // the closed-loop mode is back
    }
}

// A load that comes and goes while the relay runs: the cycles differ, the result is refused.
TEST_F(TuningMethodTest, UnsteadyCyclesAreRefusedWithWhatToChange)
{
    const Case c{"", 115200, 'N', 300, TuningRules::Rule::Medium, "not steady"};
    open(c);
    auto relay = std::make_shared<std::atomic<bool>>(false);
    QObject::connect(runner.get(), &TuningRunner::phase, runner.get(), [relay](const QString& p) {
        if (p.startsWith(QStringLiteral("Relay test")))
            *relay = true;
    });
    auto simBus = line.bus;
    double next = 0;
    bool coupled = false;
    line.backend->beforeTransaction = [relay, simBus, next, coupled](double now) mutable {
        if (!*relay || now < next)
            return;
        next = now + 110; // on and off every 110 ms, out of step with the relay's 70 ms cycles
        coupled = !coupled;
        simBus->control(
            7, {QStringLiteral("motor"), QStringLiteral("load=%1").arg(coupled ? 0.2 : 0.0)});
    };
    const Outcome r = tuneAndCheck(c);
    print(c, r);
    expectCase(c, r);
    EXPECT_TRUE(r.tune.advice.contains(QStringLiteral("amplitude"))) << qPrintable(r.tune.advice);
}

// A load that comes on as the relay starts: the output found for the speed is now too low, the
// speed spends longer below it than above.
TEST_F(TuningMethodTest, ALopsidedOscillationIsRefused)
{
    const Case c{"", 115200, 'N', 300, TuningRules::Rule::Medium, "lopsided"};
    open(c);
    QObject::connect(runner.get(), &TuningRunner::phase, runner.get(), [this](const QString& p) {
        if (p.startsWith(QStringLiteral("Relay test")))
            control({QStringLiteral("motor"), QStringLiteral("load=0.15")});
    });
    const Outcome r = tuneAndCheck(c);
    print(c, r);
    expectCase(c, r);
    EXPECT_GT(r.tune.relay.asymmetry, RelayAnalysis::kMaxAsymmetry);
}

// The plant changes between the autotune and the check (a heavy flywheel coupled on): the step
// with the accepted gains does not settle, and the verdict names it; a load with a longer
// speed gate overshoots far beyond the prediction.
TEST_F(TuningMethodTest, AStepThatDoesNotSettleFailsTheCheck)
{
    const Case c{"", 115200, 'N', 300, TuningRules::Rule::Medium, nullptr};
    open(c);
    TuningRunner::Limits limits = runner->limits();
    limits.stopTimeoutMs = 30000; // the flywheel brakes for long on the drive's 2 A
    runner->setLimits(limits);
    const TuningRunner::Result tuned = autotune(c);
    ASSERT_TRUE(tuned.ok) << qPrintable(tuned.error);
    ASSERT_TRUE(write(tuned.proposal));
    control({QStringLiteral("motor"), QStringLiteral("inertia=1e-2")});
    const TuningRunner::Result check = step(c.speed / 2, c.speed);
    const TuningVerdict v = TuningVerdict::judge(check, tuned.predictedMetrics);
    EXPECT_TRUE(v.measured);
    EXPECT_FALSE(v.passed) << qPrintable(v.text());
    EXPECT_TRUE(v.text().contains(QStringLiteral("did not settle"))) << qPrintable(v.text());
    EXPECT_TRUE(check.stopConfirmed);
    control({QStringLiteral("motor"), QStringLiteral("inertia=1e-4,gate=100,no_load=2000")});
    const TuningVerdict far =
        TuningVerdict::judge(step(c.speed / 2, c.speed), tuned.predictedMetrics);
    EXPECT_FALSE(far.passed) << qPrintable(far.text());
    EXPECT_TRUE(far.text().contains(QStringLiteral("overshot"))) << qPrintable(far.text());
    EXPECT_GT(far.overshootPercent, tuned.predictedMetrics.overshootPercent + 10);
}
