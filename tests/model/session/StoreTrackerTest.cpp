// Issue 24: which store commands a DC controller needs, from the writes this program made.
#include "model/session/StoreTracker.h"
#include "tests/model/DriveSimFixture.h"

using namespace opentop;
using namespace opentop::test;

namespace {

class StoreTrackerTest : public DriveSimFixture
{
protected:
    void write(const QString& name, const QString& text)
    {
        DeviceSession::WriteOptions explicitly;
        explicitly.explicitCommand = true;
        const auto o = await<DeviceSession::Outcome>(
            [&](auto done) { session(7)->write(name, text, explicitly, done); });
        ASSERT_TRUE(o.ok) << qPrintable(o.error);
    }
};

} // namespace

TEST_F(StoreTrackerTest, AWriteNeedsItsStoreUntilTheStoreOrAReloadIsSent)
{
    startBus(QStringLiteral("dcpid@7"));
    StoreTracker* tracker = StoreTracker::of(session(7));
    ASSERT_NE(tracker, nullptr);
    EXPECT_EQ(StoreTracker::of(session(7)), tracker) << "one per session";
    EXPECT_TRUE(tracker->unstored().isEmpty());
    write(QStringLiteral("config.rated_current"), QStringLiteral("7.5"));
    write(QStringLiteral("pid.p"), QStringLiteral("0.5"));
    EXPECT_EQ(tracker->unstored(),
              (QStringList{QStringLiteral("store.config"), QStringLiteral("store.pid")}));
    write(QStringLiteral("store.pid"), QStringLiteral("1")); // stored
    EXPECT_EQ(tracker->unstored(), QStringList{QStringLiteral("store.config")});
    write(QStringLiteral("store.config"), QStringLiteral("0")); // reloaded: the stored values act
    EXPECT_TRUE(tracker->unstored().isEmpty());
}
