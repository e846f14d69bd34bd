// One drive's recipe steps on a simulated DBU200: every way out of a run that moves the motor
// (abort, a hold limit, a wait that times out, a lost port, the runner destroyed) leaves the
// motor stopped as the simulator sees it and the priority as the drive held it (where a stop
// could be confirmed), and a good run passes through its states in order.
#include "model/eol/EolStepRunner.h"
#include "model/run/RunControl.h"
#include "tests/model/DriveSimFixture.h"

#include <QMutexLocker>
#include <QTimer>

using namespace opentop;
using namespace opentop::test;

namespace {

constexpr int kHoldIndex = 4; // in goodSteps()
constexpr double kIoPriority = 1;
constexpr double kCommunicationPriority = 2;

RecipeStep stepOf(RecipeStep::Type type)
{
    RecipeStep s;
    s.type = type;
    return s;
}

RecipeLimit limitOf(const char* parameter, const char* statistic, std::optional<double> lower,
                    std::optional<double> upper, const char* unit)
{
    return RecipeLimit{QString::fromLatin1(parameter), QString::fromLatin1(statistic), lower, upper,
                       QString::fromLatin1(unit)};
}

// The example recipe's steps on the simulator's factory SPno2 (1000 r/min, 0.5 s ramps).
QVector<RecipeStep> goodSteps(double holdS = 1)
{
    RecipeStep select = stepOf(RecipeStep::Type::Select);
    select.spno = 2;
    RecipeStep start = stepOf(RecipeStep::Type::Start);
    start.direction = QStringLiteral("cw");
    RecipeStep wait = stepOf(RecipeStep::Type::WaitSpeed);
    wait.target = 1000;
    wait.tolerance = 50;
    wait.timeout = 5;
    RecipeStep hold = stepOf(RecipeStep::Type::Hold);
    hold.duration = holdS;
    hold.limits = {limitOf("status.current_speed", "mean", 950.0, 1050.0, "r/min"),
                   limitOf("status.load", "max", std::nullopt, 80.0, "%")};
    RecipeStep stop = stepOf(RecipeStep::Type::Stop);
    stop.margin = 1;
    RecipeStep read = stepOf(RecipeStep::Type::Read);
    read.limits = {limitOf("core.control_priority", "value", std::nullopt, std::nullopt, "")};
    read.equals = QStringLiteral("Communication priority");
    return {stepOf(RecipeStep::Type::Priority), select, start, wait, hold, stop,
            stepOf(RecipeStep::Type::NoAlarm),  read};
}

QStringList statesOf(std::initializer_list<const char*> names)
{
    QStringList list;
    for (const char* name : names)
        list << QString::fromLatin1(name);
    return list;
}

class EolStepRunnerTest : public DriveSimFixture
{
protected:
    void SetUp() override
    {
        startBus(QStringLiteral("dbu200@1"));
        run = std::make_unique<RunControl>(client.get(), ProfileRegistry::builtIn());
    }
    void TearDown() override
    {
        runner.reset(); // before the session and the client it uses
        run.reset();
        DriveSimFixture::TearDown();
    }

    void make(const QVector<RecipeStep>& steps)
    {
        EolStepRunner::Timing timing;
        timing.pollMs = 50;
        runner = std::make_unique<EolStepRunner>(session(1), run.get(), steps, timing);
        QObject::connect(runner.get(), &EolStepRunner::stepStarted, runner.get(),
                         [this](int index, const QString&) {
                             started << index;
                             if (index == kHoldIndex && inHold)
                                 QTimer::singleShot(300, runner.get(), inHold);
                         });
        QObject::connect(runner.get(), &EolStepRunner::measured, runner.get(),
                         [this](const Measurement& m) { measurements << m; });
    }

    EolStepRunner::Result runSteps(const QVector<RecipeStep>& steps)
    {
        make(steps);
        return await<EolStepRunner::Result>([this](auto done) { runner->start(done); }, 30000);
    }

    // A value as the simulated drive holds it now (not through the bus).
    double raw(const char* name)
    {
        QMutexLocker lock(&bus->mutex()); // the client's worker thread serves frames meanwhile
        bus->device(1)->advance(bus->nowMs());
        return bus->device(1)->raw(QString::fromLatin1(name)).value_or(-1);
    }
    // The simulated motor turns or is commanded to (status.driver's "running" bit).
    bool turning()
    {
        const double speed = raw("status.current_speed");
        return speed != 0 || (qint64(raw("status.driver")) & 0x2) != 0;
    }
    QStringList lastStates(int n) const
    {
        const QStringList& trail = runner->states().trail();
        return trail.mid(std::max(0, int(trail.size()) - n));
    }
    const Measurement* measurement(const QString& quantity) const
    {
        for (const Measurement& m : measurements)
            if (m.quantity == quantity)
                return &m;
        return nullptr;
    }

    std::unique_ptr<RunControl> run;
    std::unique_ptr<EolStepRunner> runner;
    std::function<void()> inHold; // runs 300 ms into the hold step
    QVector<int> started;
    QVector<Measurement> measurements;
};

} // namespace

TEST_F(EolStepRunnerTest, AGoodRunPassesThroughItsStatesInOrder)
{
    ASSERT_EQ(raw("core.control_priority"), kIoPriority);
    const EolStepRunner::Result r = runSteps(goodSteps());
    EXPECT_TRUE(r.ok) << qPrintable(r.failure);
    EXPECT_TRUE(r.failure.isEmpty());
    EXPECT_TRUE(r.stopConfirmed);
    EXPECT_FALSE(runner->isRunning());
    EXPECT_EQ(runner->states().trail(),
              statesOf({"priority", "command", "command", "wait speed", "hold", "stop", "no alarm",
                        "read", "giving back", "done"}));
    EXPECT_EQ(started, QVector<int>({0, 1, 2, 3, 4, 5, 6, 7}));
    // Time to speed, two hold statistics, time to stop, no alarm, the read.
    EXPECT_EQ(measurements.size(), 6);
    for (const Measurement& m : measurements)
        EXPECT_TRUE(m.pass) << qPrintable(m.quantity);
    EXPECT_FALSE(turning());
    EXPECT_EQ(raw("core.control_priority"), kIoPriority);
}

TEST_F(EolStepRunnerTest, AbortDuringAHoldStopsTheMotorAndGivesPriorityBack)
{
    inHold = [this] { runner->abort(QStringLiteral("cancelled by the test")); };
    const EolStepRunner::Result r = runSteps(goodSteps(30));
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(r.failure, QStringLiteral("cancelled by the test"));
    EXPECT_TRUE(r.stopConfirmed) << qPrintable(r.stopDetail);
    EXPECT_TRUE(r.stopDetail.startsWith(QStringLiteral("stopped after")))
        << qPrintable(r.stopDetail);
    EXPECT_EQ(lastStates(4), statesOf({"hold", "stopping", "giving back", "done"}));
    EXPECT_FALSE(turning());
    EXPECT_EQ(raw("core.control_priority"), kIoPriority);
}

TEST_F(EolStepRunnerTest, AHoldLimitFailingStopsTheMotorAndGivesPriorityBack)
{
    QVector<RecipeStep> steps = goodSteps();
    steps[kHoldIndex].limits = {
        limitOf("status.current_speed", "max", std::nullopt, 900.0, "r/min")};
    const EolStepRunner::Result r = runSteps(steps);
    EXPECT_FALSE(r.ok);
    EXPECT_TRUE(r.failure.startsWith(QStringLiteral("step 5 ("))) << qPrintable(r.failure);
    EXPECT_TRUE(r.failure.contains(QStringLiteral("allowed at most 900 r/min")))
        << qPrintable(r.failure);
    const Measurement* max = measurement(QStringLiteral("Current speed max"));
    ASSERT_TRUE(max);
    EXPECT_FALSE(max->pass);
    EXPECT_TRUE(r.stopConfirmed) << qPrintable(r.stopDetail);
    EXPECT_EQ(lastStates(4), statesOf({"hold", "stopping", "giving back", "done"}));
    EXPECT_FALSE(turning());
    EXPECT_EQ(raw("core.control_priority"), kIoPriority);
}

TEST_F(EolStepRunnerTest, AWaitForSpeedThatTimesOutStopsTheMotorAndGivesPriorityBack)
{
    QVector<RecipeStep> steps = goodSteps();
    steps[3].target = 2500; // SPno2 runs at 1000 r/min
    steps[3].tolerance = 10;
    steps[3].timeout = 1;
    const EolStepRunner::Result r = runSteps(steps);
    EXPECT_FALSE(r.ok);
    EXPECT_TRUE(r.failure.contains(QStringLiteral("did not reach 2500 r/min ±10 r/min within 1 s")))
        << qPrintable(r.failure);
    const Measurement* wait = measurement(QStringLiteral("time to reach speed"));
    ASSERT_TRUE(wait);
    EXPECT_FALSE(wait->pass);
    EXPECT_GE(wait->value, 1.0);
    EXPECT_TRUE(r.stopConfirmed) << qPrintable(r.stopDetail);
    EXPECT_EQ(lastStates(4), statesOf({"wait speed", "stopping", "giving back", "done"}));
    EXPECT_FALSE(turning());
    EXPECT_EQ(raw("core.control_priority"), kIoPriority);
}

// The port goes away mid-hold: the polls fail, the stop cannot be sent, so it is not confirmed
// and the priority is not given back (it goes back only after a confirmed stop). A DBU has no
// communication-loss stop: its motor turns on until someone reaches it (EolRun reports it as
// NOT CONFIRMED STOPPED).
TEST_F(EolStepRunnerTest, ALostPortEndsTheStepsWithTheStopNotConfirmed)
{
    inHold = [this] { bus->setUnplugged(true); };
    const EolStepRunner::Result r = runSteps(goodSteps(30));
    EXPECT_FALSE(r.ok);
    EXPECT_TRUE(r.failure.contains(QStringLiteral("the drive stopped answering")))
        << qPrintable(r.failure);
    EXPECT_FALSE(r.stopConfirmed);
    EXPECT_TRUE(r.stopDetail.startsWith(QStringLiteral("the stop command failed")))
        << qPrintable(r.stopDetail);
    EXPECT_EQ(lastStates(3), statesOf({"hold", "stopping", "done"}));
    EXPECT_TRUE(turning());
    EXPECT_EQ(raw("core.control_priority"), kCommunicationPriority);
}

// Deleted mid-hold while its session lives on: the stop is sent as it goes; the priority stays
// with the bus (no stop was confirmed), and the hold's late answers find no runner.
TEST_F(EolStepRunnerTest, ARunnerDestroyedMidHoldStopsTheMotor)
{
    make(goodSteps(30));
    runner->start(
        [](const EolStepRunner::Result&) { ADD_FAILURE() << "a deleted runner reports"; });
    ASSERT_TRUE(waitUntil([this] { return started.contains(kHoldIndex); }, 15000));
    waitUntil([] { return false; }, 300); // into the hold, a poll under way
    ASSERT_TRUE(turning());
    runner.reset();
    EXPECT_TRUE(waitUntil([this] { return !turning(); }, 5000));
    waitUntil([] { return false; }, 300); // the answers still on their way arrive
    EXPECT_EQ(raw("core.control_priority"), kCommunicationPriority);
}
