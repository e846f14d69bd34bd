// The groups of a connected bus kept up to date: read at identification, changed by a write of
// the group setting, and a write acknowledged by a parent read again on its children.
#include "model/bus/BusGroupTracker.h"
#include "model/session/DeviceParameters.h"
#include "tests/model/DriveSimFixture.h"

#include <algorithm>

using namespace opentop;
using namespace opentop::test;

namespace {
using BusGroupTrackerTest = DriveSimFixture;
} // namespace

TEST_F(BusGroupTrackerTest, GroupsAreReadAndAParentsWriteIsReadAgainOnItsChildren)
{
    startBus(QStringLiteral("dbu200@1,dbu200@2,dbu400@150,dcpid@7"));
    control(2, {QStringLiteral("set"), QStringLiteral("0x00F5"), QStringLiteral("1")});
    control(150, {QStringLiteral("set"), QStringLiteral("0x00F5"), QStringLiteral("1")});
    auto drives = identifiedDrives({1, 2, 150, 7});
    auto* tracker = new BusGroupTracker(drives.get());
    EXPECT_EQ(BusGroupTracker::of(drives->session(2)), tracker);
    ASSERT_TRUE(waitUntil(
        [&] { return tracker->isKnown(1) && tracker->isKnown(2) && tracker->isKnown(150); }));
    EXPECT_EQ(tracker->groups().childrenOf(1), (QVector<int>{2, 150}));
    EXPECT_TRUE(tracker->isKnown(7)); // no group setting: nothing to read
    EXPECT_TRUE(tracker->groups().problems().isEmpty());

    // The tracker tells every session which drives its writes reach.
    EXPECT_EQ(drives->session(1)->reachedDrives(),
              (QVector<DeviceSession*>{drives->session(2), drives->session(150)}));
    EXPECT_TRUE(drives->session(2)->reachedDrives().isEmpty());
    // The children's copies are read, not assumed: read them once, then write the parent. The
    // write itself reads the setting back from them.
    DeviceParameters* child = drives->parameters(150);
    bool read = false;
    child->refresh({QStringLiteral("spno2.speed")}, [&](int) { read = true; });
    ASSERT_TRUE(waitUntil([&] { return read; }));
    ASSERT_NE(child->entry(QStringLiteral("spno2.speed"))->device.number, 1777);
    QVector<int> reread;
    QObject::connect(tracker, &BusGroupTracker::childrenReread,
                     [&](int parent, const QVector<int>& children, const QStringList&) {
                         EXPECT_EQ(parent, 1);
                         reread = children;
                     });
    DeviceParameters* parent = drives->parameters(1);
    ASSERT_TRUE(
        parent->setPending(QStringLiteral("spno2.speed"), QStringLiteral("1777")).isEmpty());
    int writeFailed = -1;
    parent->write({}, [&](int f) { writeFailed = f; });
    ASSERT_TRUE(waitUntil([&] { return writeFailed >= 0; }));
    EXPECT_EQ(writeFailed, 0);
    EXPECT_TRUE(reread.isEmpty()); // a setting: read back by the write, not again
    EXPECT_EQ(child->entry(QStringLiteral("spno2.speed"))->device.number, 1777);
    EXPECT_EQ(drives->parameters(2)->entry(QStringLiteral("spno2.speed"))->device.number, 1777);

    // A command (write-only) to the parent: what is known of the children is read again.
    reread.clear();
    const auto before = log.entries();
    const int readsBefore =
        int(std::count_if(before.begin(), before.end(), [](const TrafficEntry& e) {
            return e.direction == TrafficEntry::Direction::Tx && e.slave == 150 && e.function == 3;
        }));
    DeviceSession::WriteOptions command;
    command.explicitCommand = true; // as the alarm page sends it after asking
    bool sent = false;
    drives->session(1)->write(QStringLiteral("cmd.alarm_reset"), QStringLiteral("0"), command,
                              [&](const DeviceSession::Outcome& o) {
                                  EXPECT_TRUE(o.ok) << qPrintable(o.error);
                                  sent = true;
                              });
    ASSERT_TRUE(waitUntil([&] { return sent && !reread.isEmpty(); }));
    const auto after = log.entries();
    const int readsAfter = int(std::count_if(after.begin(), after.end(), [](const TrafficEntry& e) {
        return e.direction == TrafficEntry::Direction::Tx && e.slave == 150 && e.function == 3;
    }));
    EXPECT_GT(readsAfter, readsBefore);

    // A group written to a child changes the groups at once (its read-back).
    DeviceParameters* two = drives->parameters(2);
    ASSERT_TRUE(
        two->setPending(QStringLiteral("comm.group"), QStringLiteral("Disabled")).isEmpty());
    two->write({});
    ASSERT_TRUE(waitUntil([&] { return tracker->groups().childrenOf(1) == QVector<int>{150}; }));
    // A group number nobody has is a problem.
    control(150, {QStringLiteral("set"), QStringLiteral("0x00F5"), QStringLiteral("99")});
    bool done = false;
    tracker->readAll([&](int failed) {
        EXPECT_EQ(failed, 0);
        done = true;
    });
    ASSERT_TRUE(waitUntil([&] { return done; }));
    ASSERT_EQ(tracker->groups().problems().size(), 1);
    EXPECT_EQ(tracker->groups().problems().first().kind, BusGroups::ProblemKind::MissingParent);
    drives->remove(150);
    EXPECT_FALSE(tracker->groups().contains(150));
}
