// Speed-loop tests on a simulated DC controller: step responses with poor and good gains, the
// relay autotune's proposal, the test's limits, and what a test leaves behind in the drive.
#include "model/tuning/TuningRunner.h"

#include "tests/model/DriveSimFixture.h"
#include <QMutexLocker>

using namespace opentop;
using namespace opentop::test;

namespace {

class TuningRunnerTest : public DriveSimFixture
{
protected:
    void SetUp() override
    {
        startBus(QStringLiteral("dcpid@7"));
        control(7, {QStringLiteral("set"), QStringLiteral("0x0080"), QStringLiteral("2")});
        QString error;
        spec = *TuningSpec::of(session(7)->profile(), &error);
        runner = std::make_unique<TuningRunner>(session(7), spec);
        TuningRunner::Limits limits;
        limits.maxSpeed = 900;
        limits.maxCurrent = 15;
        runner->setLimits(limits);
    }
    void TearDown() override
    {
        runner.reset();
        DriveSimFixture::TearDown();
    }
    TuningRunner::Result step(double from, double to, int recordMs = 1200)
    {
        TuningRunner::StepPlan plan;
        plan.from = from;
        plan.to = to;
        plan.recordMs = recordMs;
        return await<TuningRunner::Result>([&](auto done) { runner->startStep(plan, done); },
                                           30000);
    }
    bool setGains(const PidGains& g)
    {
        bool ok = false;
        await<bool>([&](auto done) {
            runner->writeGains(g, [&ok, done](bool written, const PidGains&, const QString&) {
                ok = written;
                done(written);
            });
        });
        return ok;
    }
    PidGains gains()
    {
        PidGains out;
        await<bool>([&](auto done) {
            runner->readGains([&out, done](bool ok, const PidGains& g, const QString&) {
                out = g;
                done(ok);
            });
        });
        return out;
    }
    double raw(const char* name)
    {
        QMutexLocker lock(&bus->mutex()); // the client's worker thread serves frames meanwhile
        bus->device(7)->advance(bus->nowMs());
        return bus->device(7)->raw(QString::fromLatin1(name)).value_or(-1);
    }

    TuningSpec spec;
    std::unique_ptr<TuningRunner> runner;
};

PidGains pid(double p, double i, double d = 0, int dPeriod = 10)
{
    PidGains g;
    g.p = p;
    g.i = i;
    g.d = d;
    g.dPeriodMs = dPeriod;
    return g;
}

} // namespace

TEST_F(TuningRunnerTest, HighProportionalGainOscillatesAndAutotunedGainsSettle)
{
    ASSERT_TRUE(setGains(pid(10, 0.1)));
    const TuningRunner::Result high = step(200, 500);
    ASSERT_TRUE(high.ok) << qPrintable(high.error);
    EXPECT_FALSE(high.metrics.settlingMs) << "settled in " << *high.metrics.settlingMs << " ms";
    EXPECT_TRUE(high.stopConfirmed);

    TuningRunner::RelayPlan relay;
    relay.speed = 400;
    relay.amplitude = 10;
    relay.rule = TuningRules::Rule::Medium;
    const TuningRunner::Result tuned =
        await<TuningRunner::Result>([&](auto done) { runner->startAutotune(relay, done); }, 30000);
    ASSERT_TRUE(tuned.ok) << qPrintable(tuned.error);
    EXPECT_TRUE(tuned.relay.ok);
    EXPECT_GT(tuned.ultimateGain, 1);
    EXPECT_LT(tuned.ultimateGain, 10); // P = 10 oscillates: the ultimate gain is below it
    EXPECT_FALSE(tuned.predicted.isEmpty());
    EXPECT_EQ(raw("config.speed_mode"), 2); // the closed-loop mode is back
    EXPECT_EQ(raw("status.commutation"), 0);

    ASSERT_TRUE(setGains(tuned.proposal));
    const TuningRunner::Result good = step(200, 500);
    ASSERT_TRUE(good.ok) << qPrintable(good.error);
    ASSERT_TRUE(good.metrics.settlingMs) << qPrintable(tuned.proposal.toString());
    EXPECT_LT(*good.metrics.settlingMs, 600);
    EXPECT_LT(good.metrics.overshootPercent, 30);
    EXPECT_NEAR(good.metrics.steadyStateError, 0, 10);
    EXPECT_GT(good.metrics.peakCurrent, 1);
}

TEST_F(TuningRunnerTest, LimitExceededMidTestStopsTheMotorAndRestoresTheDrive)
{
    ASSERT_TRUE(setGains(pid(1, 0.1))); // overshoots by about a third
    TuningRunner::Limits limits = runner->limits();
    limits.maxSpeed = 450;
    runner->setLimits(limits);
    const double lossBefore = raw("config.comm_loss_time");
    const TuningRunner::Result r = step(0, 400);
    EXPECT_FALSE(r.ok);
    EXPECT_TRUE(r.aborted);
    EXPECT_TRUE(r.error.contains(QStringLiteral("450"))) << qPrintable(r.error);
    EXPECT_TRUE(r.stopConfirmed) << qPrintable(r.stopDetail);
    EXPECT_EQ(raw("status.commutation"), 0);
    EXPECT_EQ(raw("config.comm_loss_time"), lossBefore);
    EXPECT_EQ(raw("config.speed_mode"), 2);
}

TEST_F(TuningRunnerTest, CommunicationLossBrakingIsSetWhileTheTestRuns)
{
    double during = -1;
    QObject::connect(runner.get(), &TuningRunner::sampled, runner.get(),
                     [&] { during = raw("config.comm_loss_time"); });
    const TuningRunner::Result r = step(0, 300, 400);
    ASSERT_TRUE(r.ok) << qPrintable(r.error);
    EXPECT_EQ(during, 5); // 0.5 s
    EXPECT_EQ(raw("config.comm_loss_time"), 0);
}

TEST_F(TuningRunnerTest, CancelStopsAndRejectRestoresTheGains)
{
    const PidGains before = gains();
    ASSERT_TRUE(setGains(pid(2.5, 0.12, 0.4, 5)));
    EXPECT_EQ(gains(), pid(2.5, 0.12f, 0.4f, 5)) << qPrintable(gains().toString());
    ASSERT_TRUE(setGains(before)); // what reject does
    EXPECT_EQ(gains(), before);

    TuningRunner::Result result;
    bool finished = false;
    TuningRunner::StepPlan plan;
    plan.from = 0;
    plan.to = 500;
    plan.recordMs = 5000;
    runner->startStep(plan, [&](const TuningRunner::Result& r) {
        result = r;
        finished = true;
    });
    EXPECT_TRUE(waitUntil([&] { return raw("status.commutation") > 100; }, 15000));
    runner->cancel();
    ASSERT_TRUE(waitUntil([&] { return finished; }, 20000));
    EXPECT_TRUE(result.aborted);
    EXPECT_TRUE(result.stopConfirmed);
    EXPECT_EQ(raw("status.commutation"), 0);
}

TEST_F(TuningRunnerTest, RefusesOutsideAClosedLoopModeWithoutMoving)
{
    control(7, {QStringLiteral("set"), QStringLiteral("0x0080"), QStringLiteral("0")});
    const int writesBefore = framesSent(0x06) + framesSent(0x10);
    const TuningRunner::Result r = step(0, 300);
    EXPECT_FALSE(r.ok);
    EXPECT_FALSE(r.aborted);
    EXPECT_TRUE(r.error.contains(QStringLiteral("closed-loop"))) << qPrintable(r.error);
    EXPECT_EQ(framesSent(0x06) + framesSent(0x10), writesBefore);
}

TEST_F(TuningRunnerTest, ARunnerDestroyedMidTestStopsTheMotor)
{
    TuningRunner::StepPlan plan;
    plan.to = 500;
    plan.recordMs = 5000;
    runner->startStep(plan, [](const TuningRunner::Result&) { ADD_FAILURE() << "no result"; });
    ASSERT_TRUE(waitUntil([&] { return raw("status.commutation") > 100; }, 15000));
    runner.reset();
    EXPECT_TRUE(waitUntil([&] { return raw("status.commutation") == 0; }, 5000));
}

namespace {

// Two DC controllers on a 19200 bit/s line with wire timing; drive 8 read without pause while
// drive 7 is tuned, as the window's status poller does.
class TuningRunnerSlowLineTest : public DriveSimFixture
{
protected:
    void SetUp() override
    {
        startBus(QStringLiteral("dcpid@7,dcpid@8"), 19200);
        control(7, {QStringLiteral("set"), QStringLiteral("0x0080"), QStringLiteral("2")});
        QString error;
        spec = *TuningSpec::of(session(7)->profile(), &error);
        runner = std::make_unique<TuningRunner>(session(7), spec);
        TuningRunner::Limits limits;
        limits.maxSpeed = 450;
        limits.maxCurrent = 12;
        runner->setLimits(limits);
    }
    void TearDown() override
    {
        polling = false;
        runner.reset();
        DriveSimFixture::TearDown();
    }
    void pollOther()
    {
        if (!polling)
            return;
        session(8)->readMany({QStringLiteral("status.pwm"), QStringLiteral("status.current"),
                              QStringLiteral("status.commutation")},
                             [this](const DeviceSession::ReadManyOutcome&) { pollOther(); });
    }

    double raw(const char* name)
    {
        QMutexLocker lock(&bus->mutex());
        bus->device(7)->advance(bus->nowMs());
        return bus->device(7)->raw(QString::fromLatin1(name)).value_or(-1);
    }

    TuningSpec spec;
    std::unique_ptr<TuningRunner> runner;
    bool polling = true;
};

} // namespace

// The case: 300 1/s, 10 %, medium, at 19200 bit/s with another drive polled. The relay
// switches on the bus's rhythm; its result is refused, with what to change, and the motor is
// stopped and the closed-loop mode back.
TEST_F(TuningRunnerSlowLineTest, ARelayPacedByTheBusIsRefused)
{
    pollOther();
    TuningRunner::RelayPlan relay;
    relay.speed = 300;
    relay.amplitude = 10;
    relay.rule = TuningRules::Rule::Medium;
    const TuningRunner::Result r =
        await<TuningRunner::Result>([&](auto done) { runner->startAutotune(relay, done); }, 60000);
    EXPECT_FALSE(r.ok) << qPrintable(r.proposal.toString());
    EXPECT_TRUE(r.error.contains(QStringLiteral("readings"))) << qPrintable(r.error);
    EXPECT_TRUE(r.advice.contains(QStringLiteral("line rate"))) << qPrintable(r.advice);
    EXPECT_LT(r.relay.readingsPerPeriod, RelayAnalysis::kMinReadingsPerPeriod);
    EXPECT_TRUE(r.stopConfirmed) << qPrintable(r.stopDetail);
    polling = false;
    EXPECT_EQ(raw("config.speed_mode"), 2);
    EXPECT_EQ(raw("status.commutation"), 0);
}

// The port goes away mid-test: the runner gives up after its failed polls, says the stop could
// not be confirmed, and the drive brakes by itself on the communication-loss time set for it.
TEST_F(TuningRunnerTest, ALostPortEndsTheTestAndTheDriveBrakesByItself)
{
    TuningRunner::Result result;
    bool finished = false;
    TuningRunner::StepPlan plan;
    plan.to = 400;
    plan.recordMs = 5000;
    runner->startStep(plan, [&](const TuningRunner::Result& r) {
        result = r;
        finished = true;
    });
    ASSERT_TRUE(waitUntil([&] { return raw("status.commutation") > 100; }, 15000));
    EXPECT_EQ(raw("config.comm_loss_time"), 5); // 0.5 s while the test runs
    bus->setUnplugged(true);
    ASSERT_TRUE(waitUntil([&] { return finished; }, 20000));
    EXPECT_FALSE(result.ok);
    EXPECT_TRUE(result.aborted);
    EXPECT_FALSE(result.stopConfirmed);
    EXPECT_TRUE(result.stopDetail.contains(QStringLiteral("could not be confirmed")))
        << qPrintable(result.stopDetail);
    // No frame reaches the drive any more: it brakes on its own within the 0.5 s.
    EXPECT_TRUE(waitUntil([&] { return raw("status.commutation") == 0; }, 5000));
}

// The states a test goes through, by name: a step from 0 (straight from the approach to the
// record), with the communication-loss time set and restored.
TEST_F(TuningRunnerTest, AStepTestGoesThroughItsNamedStatesInOrder)
{
    const TuningRunner::Result r = step(0, 300, 400);
    ASSERT_TRUE(r.ok) << qPrintable(r.error);
    EXPECT_EQ(runner->stateTrail().join(QStringLiteral(", ")).toStdString(),
              "prepare, set comm-loss, approach, record, stop motor, restore comm-loss, reported");
    EXPECT_FALSE(runner->isRunning());
}

TEST_F(TuningRunnerTest, AnAutotuneGoesThroughItsNamedStatesInOrder)
{
    ASSERT_TRUE(setGains(pid(10, 0.1))); // as in the test above that autotunes
    TuningRunner::RelayPlan relay;
    relay.speed = 400;
    relay.amplitude = 10;
    relay.rule = TuningRules::Rule::Medium;
    const TuningRunner::Result r =
        await<TuningRunner::Result>([&](auto done) { runner->startAutotune(relay, done); }, 30000);
    ASSERT_TRUE(r.ok) << qPrintable(r.error);
    QStringList trail = runner->stateTrail();
    // A second hold only when the first guess of the output was off by more than 1 %.
    const int holds = int(trail.count(QStringLiteral("estimate")));
    EXPECT_TRUE(holds == 1 || holds == 2) << holds << " holds";
    trail.removeDuplicates();
    EXPECT_EQ(trail.join(QStringLiteral(", ")).toStdString(),
              "prepare, set comm-loss, open loop, estimate, relay, conclude, stop motor, "
              "restore mode, restore comm-loss, reported");
}

// Cancelled while the relay switches (not only during a step): the motor is stopped and the
// stop confirmed, the closed-loop mode and the communication-loss time are back.
TEST_F(TuningRunnerTest, CancelDuringTheRelayStopsTheMotorAndRestoresModeAndCommLoss)
{
    const double lossBefore = raw("config.comm_loss_time");
    QObject::connect(runner.get(), &TuningRunner::phase, runner.get(), [this](const QString& p) {
        if (p.startsWith(QStringLiteral("Relay test")))
            runner->cancel();
    });
    TuningRunner::RelayPlan relay;
    relay.speed = 400;
    relay.amplitude = 10;
    const TuningRunner::Result r =
        await<TuningRunner::Result>([&](auto done) { runner->startAutotune(relay, done); }, 30000);
    EXPECT_FALSE(r.ok);
    EXPECT_TRUE(r.aborted);
    EXPECT_EQ(r.error, QStringLiteral("cancelled"));
    EXPECT_TRUE(r.stopConfirmed) << qPrintable(r.stopDetail);
    const QStringList trail = runner->stateTrail();
    const int relayAt = int(trail.indexOf(QStringLiteral("relay")));
    ASSERT_GE(relayAt, 0) << qPrintable(trail.join(QStringLiteral(", ")));
    EXPECT_EQ(trail.mid(relayAt).join(QStringLiteral(", ")).toStdString(),
              "relay, stop motor, restore mode, restore comm-loss, reported");
    EXPECT_TRUE(waitUntil([&] { return raw("status.commutation") == 0; }, 5000));
    EXPECT_EQ(raw("config.speed_mode"), 2);
    EXPECT_EQ(raw("config.comm_loss_time"), lossBefore);
}

// Refused before anything was sent: no stop to wait for, straight to the report.
TEST_F(TuningRunnerTest, ARefusalBeforeAnythingMovesSkipsTheStop)
{
    control(7, {QStringLiteral("set"), QStringLiteral("0x0080"), QStringLiteral("0")});
    const TuningRunner::Result r = step(0, 300);
    EXPECT_FALSE(r.ok);
    EXPECT_TRUE(r.stopDetail.isEmpty()) << qPrintable(r.stopDetail);
    EXPECT_EQ(runner->stateTrail().join(QStringLiteral(", ")).toStdString(), "prepare, reported");
}
