// Test runs and stop-all against the in-process simulated bus.
#include "model/run/RunControl.h"
#include "tests/model/DriveSimFixture.h"

using namespace opentop;
using namespace opentop::test;

namespace {

class RunControlTest : public DriveSimFixture
{
protected:
    RunControl::Outcome run(int slave, const QStringList& words)
    {
        QString error;
        const std::optional<RunControl::Command> command = RunControl::parse(words, &error);
        EXPECT_TRUE(command) << qPrintable(error);
        RunControl control(client.get(), ProfileRegistry::builtIn());
        return await<RunControl::Outcome>(
            [&](auto done) { control.execute(session(slave), *command, done); });
    }

    double speed(int slave)
    {
        const auto o = await<DeviceSession::Outcome>(
            [&](auto done) { session(slave)->read(QStringLiteral("status.current_speed"), done); });
        return o.value.number;
    }
};

} // namespace

TEST_F(RunControlTest, ParsesCommandsAndRefusesOthers)
{
    QString error;
    EXPECT_EQ(RunControl::parse({QStringLiteral("START")}, &error)->action,
              RunControl::Action::Start);
    const auto select = RunControl::parse({QStringLiteral("select"), QStringLiteral("3")}, &error);
    ASSERT_TRUE(select);
    EXPECT_EQ(select->select, 3);
    EXPECT_FALSE(RunControl::parse({QStringLiteral("select")}, &error));
    EXPECT_FALSE(RunControl::parse({QStringLiteral("select"), QStringLiteral("x")}, &error));
    EXPECT_FALSE(RunControl::parse({QStringLiteral("start"), QStringLiteral("1")}, &error));
    EXPECT_FALSE(RunControl::parse({QStringLiteral("jump")}, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("select N"))) << qPrintable(error);
}

TEST_F(RunControlTest, StartedDriveRampsUpAndStops)
{
    startBus(QStringLiteral("dbu200@1"));
    communicationPriority(1);
    // A slower ramp for SPno2 so that the ramp can be seen: 1000 r/min in 0.67 s.
    DeviceSession::WriteOptions plain;
    ASSERT_TRUE(await<DeviceSession::Outcome>([&](auto done) {
                    session(1)->write(QStringLiteral("spno2.accel"), QStringLiteral("2.0"), plain,
                                      done);
                }).ok);
    ASSERT_TRUE(run(1, {QStringLiteral("select"), QStringLiteral("2")}).ok);
    const RunControl::Outcome started = run(1, {QStringLiteral("start")});
    ASSERT_TRUE(started.ok) << qPrintable(started.error);
    EXPECT_TRUE(started.sent);
    EXPECT_TRUE(started.plan.description.contains(QStringLiteral("run.start = START (1)")));
    bool sawRamp = false;
    EXPECT_TRUE(waitUntil([&] {
        const double s = speed(1);
        sawRamp = sawRamp || (s > 0 && s < 1000);
        return s == 1000;
    }));
    EXPECT_TRUE(sawRamp);

    RunControl control(client.get(), ProfileRegistry::builtIn());
    const RunControl::State state =
        await<RunControl::State>([&](auto done) { control.readState(session(1), done); });
    EXPECT_TRUE(state.ok) << qPrintable(state.error);
    EXPECT_EQ(state.running, std::optional<bool>(true));
    EXPECT_TRUE(state.items.contains({QStringLiteral("Running direction"), QStringLiteral("CW")}));
    EXPECT_TRUE(
        state.items.contains({QStringLiteral("Current speed"), QStringLiteral("1000 r/min")}));
    EXPECT_TRUE(
        state.items.contains({QStringLiteral("Select running data"), QStringLiteral("SPno2")}));

    ASSERT_TRUE(run(1, {QStringLiteral("ccw")}).ok);
    ASSERT_TRUE(run(1, {QStringLiteral("stop")}).ok);
    EXPECT_TRUE(waitUntil([&] { return speed(1) == 0; }));
}

TEST_F(RunControlTest, IoPriorityIsRefusedWithNothingSent)
{
    startBus(QStringLiteral("dbu200@1"));
    const int writesBefore = framesSent(0x06) + framesSent(0x10);
    const RunControl::Outcome o = run(1, {QStringLiteral("start")});
    EXPECT_FALSE(o.ok);
    EXPECT_FALSE(o.sent);
    EXPECT_EQ(o.failure, RunControl::Failure::Priority);
    EXPECT_TRUE(o.error.contains(QStringLiteral("I/O priority"))) << qPrintable(o.error);
    EXPECT_TRUE(o.explanation.contains(QStringLiteral("input terminals")))
        << qPrintable(o.explanation);
    EXPECT_TRUE(o.explanation.contains(QStringLiteral("set 1 core.control_priority=2")))
        << qPrintable(o.explanation);
    EXPECT_EQ(framesSent(0x06) + framesSent(0x10), writesBefore);
    EXPECT_EQ(speed(1), 0);
}

TEST_F(RunControlTest, SelectOutsideTheRunningDataIsRefusedBeforeSending)
{
    startBus(QStringLiteral("dbu200@1"));
    communicationPriority(1);
    const int before = framesSent();
    for (const char* n : {"0", "9"}) {
        const RunControl::Outcome o = run(1, {QStringLiteral("select"), QLatin1String(n)});
        EXPECT_EQ(o.failure, RunControl::Failure::InvalidValue);
        EXPECT_TRUE(o.error.contains(QStringLiteral("choose 1–8 (SPno1 … SPno8)")))
            << qPrintable(o.error);
    }
    EXPECT_EQ(framesSent(), before);
    // SPno8 is code 7 (erratum DBU-2).
    const RunControl::Plan plan =
        RunControl::plan(*session(1), {RunControl::Action::Select, 8, {}});
    EXPECT_TRUE(plan.description.contains(QStringLiteral("SPno8 (7)")))
        << qPrintable(plan.description);
}

TEST_F(RunControlTest, ActionsFollowTheFamilysRoles)
{
    startBus(QStringLiteral("dcpid@7"));
    const RunControl::Outcome o = run(7, {QStringLiteral("start")});
    EXPECT_EQ(o.failure, RunControl::Failure::Unsupported);
    EXPECT_TRUE(o.error.contains(QStringLiteral("stop, coast, speed VALUE")))
        << qPrintable(o.error);

    // The DC controller runs on a speed set point and stops on 0.
    const RunControl::Outcome fast = run(7, {QStringLiteral("speed"), QStringLiteral("150")});
    EXPECT_EQ(fast.failure, RunControl::Failure::InvalidValue);
    EXPECT_TRUE(fast.error.contains(QStringLiteral("100.0"))) << qPrintable(fast.error);
    ASSERT_TRUE(run(7, {QStringLiteral("speed"), QStringLiteral("50")}).ok);
    auto pwm = [&] {
        return await<DeviceSession::Outcome>(
                   [&](auto done) { session(7)->read(QStringLiteral("status.pwm"), done); })
            .value.number;
    };
    EXPECT_TRUE(waitUntil([&] { return pwm() == 50; }));
    ASSERT_TRUE(run(7, {QStringLiteral("stop")}).ok);
    EXPECT_TRUE(waitUntil([&] { return pwm() == 0; }));
}

TEST_F(RunControlTest, StartDuringAnAlarmIsExplained)
{
    startBus(QStringLiteral("dbu200@1"));
    communicationPriority(1);
    control(1, {QStringLiteral("alarm"), QStringLiteral("7")});
    const RunControl::Outcome o = run(1, {QStringLiteral("start")});
    EXPECT_EQ(o.failure, RunControl::Failure::Communication);
    EXPECT_TRUE(o.sent);
    EXPECT_TRUE(o.deviceError.startsWith(QStringLiteral("E2h"))) << qPrintable(o.deviceError);
    EXPECT_TRUE(o.explanation.contains(QStringLiteral("alarms 1 --reset --yes")))
        << qPrintable(o.explanation);
}

TEST_F(RunControlTest, StopAllStopsEveryDriveAndReportsTheOneThatIgnoresStop)
{
    startBus(QStringLiteral("dbu200@1,dbu400@2,dcpid@7"));
    for (int id : {1, 2})
        communicationPriority(id);
    ASSERT_TRUE(run(1, {QStringLiteral("start")}).ok);
    ASSERT_TRUE(run(2, {QStringLiteral("select"), QStringLiteral("3")}).ok);
    ASSERT_TRUE(run(2, {QStringLiteral("start")}).ok);
    ASSERT_TRUE(run(7, {QStringLiteral("speed"), QStringLiteral("40")}).ok);
    control(2, {QStringLiteral("ignore-stop"), QStringLiteral("on")});
    EXPECT_TRUE(waitUntil([&] { return speed(1) == 500 && speed(2) == 1350; }));

    const int broadcastsBefore = [&] {
        int n = 0;
        for (const TrafficEntry& e : log.entries())
            n += e.direction == TrafficEntry::Direction::Tx && e.slave == 0 ? 1 : 0;
        return n;
    }();
    RunControl control(client.get(), ProfileRegistry::builtIn());
    QElapsedTimer timer;
    timer.start();
    const RunControl::StopReport report = await<RunControl::StopReport>([&](auto done) {
        control.stopAll({1, 2, 7, 9}, done);
    });
    EXPECT_LT(timer.elapsed(), 10000);

    ASSERT_EQ(report.broadcasts.size(), 2);
    EXPECT_TRUE(report.broadcastOk());
    int broadcasts = 0;
    for (const TrafficEntry& e : log.entries())
        broadcasts += e.direction == TrafficEntry::Direction::Tx && e.slave == 0 ? 1 : 0;
    EXPECT_EQ(broadcasts - broadcastsBefore, 2); // one per family, each once
    ASSERT_EQ(report.drives.size(), 4);
    EXPECT_EQ(report.drives[0].state, StopResult::State::Stopped);
    EXPECT_EQ(report.drives[0].speedText, QStringLiteral("0 r/min"));
    EXPECT_EQ(report.drives[1].state, StopResult::State::StillRunning);
    EXPECT_TRUE(report.drives[1].detail.contains(QStringLiteral("1350 r/min")))
        << qPrintable(report.drives[1].detail);
    EXPECT_EQ(report.drives[2].state, StopResult::State::Stopped);
    EXPECT_EQ(report.drives[2].family, QStringLiteral("dcpid"));
    EXPECT_EQ(report.drives[3].state, StopResult::State::NoAnswer);
    EXPECT_TRUE(report.anyStillRunning());
    EXPECT_TRUE(report.anyNoAnswer());
    EXPECT_EQ(speed(1), 0);
    EXPECT_EQ(speed(2), 1350);
}

// SPno1 may take the SD knob's 30 s to stop, but a drive whose speed does not fall at all after
// the stop is reported at its settings' deadline, not after the knob's.
TEST_F(RunControlTest, StopAllReportsAnSpno1DriveThatIgnoresStopWithoutWaitingForTheKnob)
{
    startBus(QStringLiteral("dbu200@1"));
    communicationPriority(1);
    ASSERT_TRUE(run(1, {QStringLiteral("select"), QStringLiteral("1")}).ok);
    ASSERT_TRUE(run(1, {QStringLiteral("start")}).ok);
    control(1, {QStringLiteral("ignore-stop"), QStringLiteral("on")});
    ASSERT_TRUE(waitUntil([&] { return speed(1) > 0; }));
    RunControl control(client.get(), ProfileRegistry::builtIn());
    QElapsedTimer timer;
    timer.start();
    const RunControl::StopReport report =
        await<RunControl::StopReport>([&](auto done) { control.stopAll({1}, done); });
    EXPECT_LT(timer.elapsed(), 10000);
    ASSERT_EQ(report.drives.size(), 1);
    EXPECT_EQ(report.drives[0].state, StopResult::State::StillRunning);
}

TEST_F(RunControlTest, StopAllExplainsADriveInIoPriority)
{
    startBus(QStringLiteral("dbu200@1"));
    // I/O priority, started through its input terminals: X0 = CW/STOP.
    control(1, {QStringLiteral("input"), QStringLiteral("1")});
    EXPECT_TRUE(waitUntil([&] { return speed(1) == 500; }));
    RunControl control(client.get(), ProfileRegistry::builtIn());
    const RunControl::StopReport report =
        await<RunControl::StopReport>([&](auto done) { control.stopAll({1}, done); });
    ASSERT_EQ(report.drives.size(), 1);
    EXPECT_EQ(report.drives[0].state, StopResult::State::StillRunning);
    EXPECT_TRUE(report.drives[0].detail.contains(QStringLiteral("input terminals")))
        << qPrintable(report.drives[0].detail);
}
