// The stop deadline of StopConfirmer against the simulated DBU: SPno1's deceleration comes from
// the SD knob, which cannot be read, so the profile's knob maximum counts while SPno1 runs.
#include "model/run/StopConfirmer.h"
#include "tests/model/DriveSimFixture.h"

using namespace opentop;
using namespace opentop::test;

namespace {

class StopConfirmerTest : public DriveSimFixture
{
protected:
    // The deadline a confirmer derives for drive 1 after running data `spno` was selected.
    qint64 deadlineWith(int spno)
    {
        communicationPriority(1);
        // run.select (0x200F) = spno - 1, through the simulator's backdoor.
        control(1, {QStringLiteral("set"), QStringLiteral("0x200F"), QString::number(spno - 1)});
        StopConfirmer::Timing timing;
        timing.maxMs = 120000; // no cap in the way of what is measured
        QElapsedTimer sinceStop;
        sinceStop.start();
        StopConfirmer confirmer(session(1), sinceStop, timing);
        const StopResult r = await<StopResult>([&](auto done) { confirmer.start(done); });
        EXPECT_EQ(r.state, StopResult::State::Stopped) << qPrintable(r.detail);
        return confirmer.expectedMs();
    }
};

} // namespace

TEST_F(StopConfirmerTest, TheKnobsMaximumCountsWhileSpno1Runs)
{
    const Profile& dbu = *ProfileRegistry::builtIn().family(QStringLiteral("dbu"));
    ASSERT_EQ(dbu.knobDeceleration(0), std::optional<double>(30.0)); // SPno1: the SD knob
    EXPECT_FALSE(dbu.knobDeceleration(1));                           // SPno2: a setting
    startBus(QStringLiteral("dbu200@1"));
    // SPno2–8 decelerate in their factory 0.5 s: 0.5 s × 1.2 + 1 s margin.
    EXPECT_EQ(deadlineWith(2), 1600);
    // SPno1: the knob may be at 30 s, 30 s × 1.2 + 1 s.
    EXPECT_EQ(deadlineWith(1), 37000);
}

TEST_F(StopConfirmerTest, WithoutKnobsOnlyTheSettingsCount)
{
    startBus(QStringLiteral("dbu200@1"));
    communicationPriority(1);
    control(1, {QStringLiteral("set"), QStringLiteral("0x200F"), QStringLiteral("0")});
    Profile noKnob = *ProfileRegistry::builtIn().family(QStringLiteral("dbu"));
    noKnob.decelerationKnobs.clear();
    DeviceSession plain(client.get(), noKnob, 1, QStringLiteral("dbu200"));
    StopConfirmer::Timing timing;
    timing.maxMs = 120000;
    QElapsedTimer sinceStop;
    sinceStop.start();
    StopConfirmer confirmer(&plain, sinceStop, timing);
    await<StopResult>([&](auto done) { confirmer.start(done); });
    EXPECT_EQ(confirmer.expectedMs(), 1600);
}
