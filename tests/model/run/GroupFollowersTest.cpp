// Which drives of a communication group follow a run command sent to their parent: a child in
// I/O priority ignores it (and shows E2h), read from the children before and after, against the
// in-process simulator whose children execute the parent's frames.
#include "model/run/GroupFollowers.h"
#include "model/run/RunControl.h"
#include "tests/model/DriveSimFixture.h"

using namespace opentop;
using namespace opentop::test;

namespace {

class GroupFollowersTest : public DriveSimFixture
{
protected:
    // Drive 1 (DBU200) parent of 2 (DBU200, communication priority) and 150 (DBU400, I/O
    // priority).
    void SetUp() override
    {
        startBus(QStringLiteral("dbu200@1,dbu200@2,dbu400@150"));
        for (int child : {2, 150})
            control(child, {QStringLiteral("set"), QStringLiteral("0x00F5"), QStringLiteral("1")});
        communicationPriority(1);
        communicationPriority(2);
    }

    QVector<GroupFollowers::Drive> read(bool after)
    {
        const QVector<DeviceSession*> children{session(2), session(150)};
        return await<QVector<GroupFollowers::Drive>>([&](auto done) {
            after ? GroupFollowers::readAfter(children, done)
                  : GroupFollowers::readBefore(children, done);
        });
    }
};

} // namespace

TEST_F(GroupFollowersTest, AChildInIoPriorityIsNamedBeforeAndReportedAfterTheStart)
{
    const QVector<GroupFollowers::Drive> before = read(false);
    ASSERT_EQ(before.size(), 2);
    EXPECT_EQ(before.at(0).follows, std::optional<bool>(true));
    EXPECT_EQ(before.at(1).follows, std::optional<bool>(false));
    EXPECT_EQ(GroupFollowers::notFollowing(before), QVector<int>{150});
    const QString lines = GroupFollowers::beforeLines(before).join(QLatin1Char('\n'));
    EXPECT_TRUE(lines.contains(QStringLiteral("Machine number 2 follows it (Communication")))
        << qPrintable(lines);
    EXPECT_TRUE(lines.contains(QStringLiteral("Machine number 150 does NOT follow it: it is in "
                                              "I/O priority")))
        << qPrintable(lines);

    RunControl control(client.get(), ProfileRegistry::builtIn());
    const RunControl::Outcome started = await<RunControl::Outcome>([&](auto done) {
        control.execute(session(1), RunControl::Command{RunControl::Action::Start, 0, {}}, done);
    });
    ASSERT_TRUE(started.ok) << qPrintable(started.error);
    // Drives update their status within a few cycles of a command.
    QElapsedTimer settle;
    settle.start();
    waitUntil([&] { return settle.elapsed() > 300; });
    const QVector<GroupFollowers::Drive> after = read(true);
    ASSERT_EQ(after.size(), 2);
    EXPECT_EQ(after.at(0).running, std::optional<bool>(true));
    EXPECT_EQ(after.at(1).running, std::optional<bool>(false));
    // The child that ignored it shows E2h, explained in words with what to do.
    EXPECT_TRUE(after.at(1).commError.startsWith(QStringLiteral("E2h Cannot execute command: ")))
        << qPrintable(after.at(1).commError);
    EXPECT_TRUE(after.at(1).commError.contains(QStringLiteral("What to do:")));
    const QString report = GroupFollowers::afterLines(after).join(QLatin1Char('\n'));
    EXPECT_TRUE(report.contains(QStringLiteral("Machine number 2 runs"))) << qPrintable(report);
    EXPECT_TRUE(report.contains(QStringLiteral("Machine number 150 does not run: it is in I/O "
                                               "priority")))
        << qPrintable(report);
}
