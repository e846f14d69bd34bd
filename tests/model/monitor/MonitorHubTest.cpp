// Shared live monitoring against the in-process simulated bus.
#include "model/monitor/MonitorHub.h"
#include "model/bus/BusDrives.h"
#include "model/profile/ProfileRegistry.h"
#include "tests/model/DriveSimFixture.h"

using namespace opentop;
using namespace opentop::test;

namespace {

class MonitorHubTest : public DriveSimFixture
{
protected:
    void start(const QString& spec, const QVector<int>& slaves)
    {
        startBus(spec);
        drives = identifiedDrives(slaves);
        hub = std::make_unique<MonitorHub>(drives.get());
        hub->setInterval(50);
    }

    void TearDown() override
    {
        hub.reset();
        drives.reset();
        DriveSimFixture::TearDown();
    }

    // Lets the event loop run for `ms`.
    void idle(int ms)
    {
        waitUntil([] { return false; }, ms);
    }

    std::unique_ptr<BusDrives> drives;
    std::unique_ptr<MonitorHub> hub;
};

} // namespace

TEST_F(MonitorHubTest, PollsWatchedDrivesOnlyAndKeepsTheirHistory)
{
    start(QStringLiteral("dbu200@1,dbu200@2"), {1, 2});
    QObject viewA;
    hub->watch(1, &viewA);
    EXPECT_EQ(hub->watched(), QVector<int>{1});
    ASSERT_TRUE(waitUntil([&] { return hub->statistics(1).samples >= 3; }));
    EXPECT_EQ(hub->statistics(2).samples, 0);
    EXPECT_FALSE(hub->latest(2));
    ASSERT_TRUE(hub->latest(1));
    EXPECT_EQ(hub->latest(1)->slave, 1);
    ASSERT_NE(hub->history(1), nullptr);
    EXPECT_GE(hub->history(1)->find(QStringLiteral("status.current_speed"))->points.size(), 3);
    // The display settings were read before the first sample.
    EXPECT_TRUE(hub->latest(1)->currentShown);
}

TEST_F(MonitorHubTest, PollingStopsWhenTheLastWatcherGoes)
{
    start(QStringLiteral("dbu200@1"), {1});
    auto a = std::make_unique<QObject>();
    QObject b;
    hub->watch(1, a.get());
    hub->watch(1, &b);
    ASSERT_TRUE(waitUntil([&] { return hub->statistics(1).samples >= 2; }));
    a.reset(); // a view closed: the other still watches
    EXPECT_TRUE(hub->isWatched(1));
    hub->unwatch(1, &b);
    EXPECT_FALSE(hub->isWatched(1));
    idle(100); // a poll under way may still finish
    const int frames = framesSent();
    idle(300);
    EXPECT_EQ(framesSent(), frames);
    // The history stays for the trends.
    EXPECT_GE(hub->history(1)->series().size(), 1);
}

TEST_F(MonitorHubTest, IntervalAndPauseApplyToEveryDrive)
{
    start(QStringLiteral("dbu200@1,dcpid@7"), {1, 7});
    QObject view;
    hub->watch(1, &view);
    hub->watch(7, &view);
    hub->setInterval(100);
    ASSERT_TRUE(waitUntil(
        [&] { return hub->statistics(1).samples >= 5 && hub->statistics(7).samples >= 5; }));
    // 100 ms start to start: about 10 samples per second each, never much more.
    EXPECT_LE(hub->statistics(1).rate(), 11.5);
    EXPECT_GE(hub->statistics(1).rate(), 6.0);
    hub->setPaused(true);
    idle(150);
    const qint64 samples = hub->statistics(1).samples + hub->statistics(7).samples;
    idle(300);
    EXPECT_EQ(hub->statistics(1).samples + hub->statistics(7).samples, samples);
    hub->setPaused(false);
    EXPECT_TRUE(waitUntil([&] { return hub->statistics(7).samples > samples; }));
}

TEST_F(MonitorHubTest, ADriveWatchedBeforeItIsIdentifiedStartsOnceItIs)
{
    startBus(QStringLiteral("dbu200@3"));
    drives = std::make_unique<BusDrives>(client.get(), ProfileRegistry::builtIn());
    hub = std::make_unique<MonitorHub>(drives.get());
    QObject view;
    hub->watch(3, &view);
    idle(100);
    EXPECT_EQ(hub->statistics(3).samples, 0);
    DeviceInfo info;
    info.slave = 3;
    info.state = DeviceInfo::State::Present;
    info.family = QStringLiteral("dbu");
    drives->update(info);
    EXPECT_TRUE(waitUntil([&] { return hub->statistics(3).samples >= 1; }));
}

TEST_F(MonitorHubTest, CommandsOvertakePollingAndTheDrivesShareTheRestEvenly)
{
    // Sixteen drives on a real-speed line (19200 bit/s): polling alone keeps the bus busy.
    startBus(QStringLiteral("dbu200@1-16"), 19200);
    drives = identifiedDrives({1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16});
    hub = std::make_unique<MonitorHub>(drives.get());
    hub->setInterval(20);
    QObject view;
    for (int s = 1; s <= 16; ++s)
        hub->watch(s, &view);
    ASSERT_TRUE(waitUntil([&] { return hub->statistics(16).samples >= 3; }, 10000));
    // A user's read while every drive has polls queued: it waits at most for the transaction
    // on the wire (about 15 ms), not for the queue (16 drives × 4 requests, 0.2–0.8 s).
    QElapsedTimer timer;
    timer.start();
    const DeviceSession::Outcome read = await<DeviceSession::Outcome>(
        [&](auto done) { drives->session(5)->read(QStringLiteral("spno2.speed"), done); });
    const qint64 elapsed = timer.elapsed();
    ASSERT_TRUE(read.ok) << qPrintable(read.error);
    EXPECT_LT(elapsed, 100);
    idle(1500);
    double lowest = 1e9;
    double highest = 0;
    for (int s = 1; s <= 16; ++s) {
        lowest = std::min(lowest, hub->statistics(s).rate());
        highest = std::max(highest, hub->statistics(s).rate());
    }
    EXPECT_GT(lowest, 0.0);
    EXPECT_GT(lowest / highest, 0.8) << lowest << " .. " << highest;
}

TEST(MonitorHubHistoryTest, ManyDrivesShareOneHistoryBudget)
{
    EXPECT_EQ(MonitorHub::historyCapacity(1), 36000);
    EXPECT_EQ(MonitorHub::historyCapacity(16), 36000);
    EXPECT_EQ(MonitorHub::historyCapacity(32), 18000);
    EXPECT_EQ(MonitorHub::historyCapacity(247), 2331);
    EXPECT_EQ(MonitorHub::historyCapacity(100000), 600);
}

TEST_F(MonitorHubTest, EachDrivesHistoryIsBoundedByTheNumberOfDrives)
{
    QVector<int> slaves;
    for (int s = 1; s <= 32; ++s)
        slaves << s;
    start(QStringLiteral("dbu200@1-32"), slaves);
    QObject view;
    hub->watch(1, &view);
    ASSERT_NE(hub->history(1), nullptr);
    EXPECT_EQ(hub->history(1)->capacity(), 36000);
    for (int s : slaves)
        hub->watch(s, &view);
    EXPECT_EQ(hub->history(1)->capacity(), 18000);
    EXPECT_EQ(hub->history(32)->capacity(), 18000);
    // Drives that leave the bus give their share back.
    for (int s = 2; s <= 32; ++s)
        drives->remove(s);
    EXPECT_EQ(hub->history(1)->capacity(), 36000);
}

// Issue 24: a drive whose pages are open keeps its trend while its monitor is out of sight,
// polled once a second; in sight again, at the chosen rate.
TEST_F(MonitorHubTest, ARecordedDriveKeepsItsTrendWhileNoViewWatchesIt)
{
    start(QStringLiteral("dbu200@1"), {1});
    QObject pages;
    QObject view;
    hub->record(1, &pages);
    hub->watch(1, &view);
    ASSERT_TRUE(waitUntil([&] { return hub->statistics(1).samples >= 3; }));
    EXPECT_FALSE(hub->isRecordingOnly(1));
    hub->unwatch(1, &view);
    EXPECT_FALSE(hub->isWatched(1));
    EXPECT_TRUE(hub->isRecordingOnly(1));
    const qint64 before = hub->statistics(1).samples;
    idle(2600);
    const qint64 recorded = hub->statistics(1).samples - before;
    // Once a second, not at the 50 ms the views use.
    EXPECT_GE(recorded, 2);
    EXPECT_LE(recorded, 4);
    // No gap in the trend: consecutive points closer than a value stays live.
    const auto& points = hub->history(1)->find(QStringLiteral("status.current_speed"))->points;
    for (int i = 1; i < points.size(); ++i)
        EXPECT_LE(points[i].ms - points[i - 1].ms, Freshness::staleAfterMs(hub->interval()));
    // Watched again: the chosen rate at once.
    hub->watch(1, &view);
    const qint64 again = hub->statistics(1).samples;
    idle(500);
    EXPECT_GE(hub->statistics(1).samples - again, 4);
    // The pages closed: nothing polls it any more.
    hub->unwatch(1, &view);
    hub->stopRecording(1, &pages);
    idle(100);
    const int frames = framesSent();
    idle(1500);
    EXPECT_EQ(framesSent(), frames);
}
