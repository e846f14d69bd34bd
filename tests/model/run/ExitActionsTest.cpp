// The exit question's default carried out by the model (issue 24 item 6): each running drive
// stopped and confirmed, then given back to its inputs (I/O priority, read back); a drive that
// did not stop keeps communication priority and the failures name it.
#include "model/run/ExitActions.h"
#include "model/run/RunControl.h"
#include "tests/model/DriveSimFixture.h"

#include <QRegularExpression>

using namespace opentop;
using namespace opentop::test;

namespace {

class ExitActionsTest : public DriveSimFixture
{
protected:
    void start(BusDrives& drives, int slave)
    {
        communicationPriority(slave);
        RunControl control(client.get(), ProfileRegistry::builtIn());
        RunControl::Command command;
        command.action = RunControl::Action::Start;
        const RunControl::Outcome o = await<RunControl::Outcome>(
            [&](auto done) { control.execute(drives.session(slave), command, done); });
        ASSERT_TRUE(o.ok) << qPrintable(o.error);
        ASSERT_TRUE(waitUntil([&] { return reg(slave, 0x0109) > 0; }));
    }

    int reg(int slave, int address)
    {
        const QString text =
            bus->control(slave, {QStringLiteral("get"), QString::number(address)}).text;
        const QRegularExpressionMatch m =
            QRegularExpression(QStringLiteral("= (\\d+) ")).match(text);
        return m.hasMatch() ? m.captured(1).toInt() : -1;
    }

    static DriveLeftBehind left(int slave, bool running)
    {
        DriveLeftBehind d;
        d.slave = slave;
        d.model = QStringLiteral("DBU200");
        d.running = running;
        d.busPriority = true;
        d.canReturn = true;
        return d;
    }
};

} // namespace

TEST_F(ExitActionsTest, TheDefaultStopsConfirmsAndGivesEachDriveBackToItsInputs)
{
    startBus(QStringLiteral("dbu200@1,dbu200@2"));
    auto drives = identifiedDrives({1, 2});
    start(*drives, 1);
    communicationPriority(2);
    ExitActions actions(drives.get());
    const QStringList failures = await<QStringList>([&](auto done) {
        actions.leave(ExitPlan({left(1, true), left(2, false)}), ExitPlan::Choice::StopAndGiveBack,
                      done);
    });
    EXPECT_TRUE(failures.isEmpty()) << qPrintable(failures.join(QLatin1Char('\n')));
    EXPECT_EQ(reg(1, 0x0109), 0);
    EXPECT_EQ(reg(1, 0x100D), 1);
    EXPECT_EQ(reg(2, 0x100D), 1);
}

TEST_F(ExitActionsTest, ADriveThatDoesNotStopKeepsCommunicationPriority)
{
    startBus(QStringLiteral("dbu200@1,dbu200@2"));
    auto drives = identifiedDrives({1, 2});
    start(*drives, 1);
    communicationPriority(2);
    control(1, {QStringLiteral("ignore-stop"), QStringLiteral("on")});
    ExitActions actions(drives.get());
    const QStringList failures = await<QStringList>(
        [&](auto done) {
            actions.leave(ExitPlan({left(1, true), left(2, false)}),
                          ExitPlan::Choice::StopAndGiveBack, done);
        },
        60000);
    const QString text = failures.join(QLatin1Char('\n'));
    EXPECT_TRUE(text.contains(QStringLiteral("Machine number 1: STILL RUNNING")))
        << qPrintable(text);
    EXPECT_TRUE(text.contains(QStringLiteral("Machine number 1: left in communication priority")))
        << qPrintable(text);
    EXPECT_FALSE(text.contains(QStringLiteral("Machine number 2"))) << qPrintable(text);
    EXPECT_GT(reg(1, 0x0109), 0);
    EXPECT_EQ(reg(1, 0x100D), 2); // not handed to its inputs while it runs
    EXPECT_EQ(reg(2, 0x100D), 1); // the other one is
}

TEST_F(ExitActionsTest, GiveControlBackOnlySendsNoStop)
{
    startBus(QStringLiteral("dbu200@1"));
    auto drives = identifiedDrives({1});
    start(*drives, 1);
    const int before = framesSent(0x06) + framesSent(0x10);
    ExitActions actions(drives.get());
    const QStringList failures = await<QStringList>([&](auto done) {
        actions.leave(ExitPlan({left(1, true)}), ExitPlan::Choice::GiveBackOnly, done);
    });
    EXPECT_TRUE(failures.isEmpty()) << qPrintable(failures.join(QLatin1Char('\n')));
    EXPECT_EQ(reg(1, 0x100D), 1);
    EXPECT_EQ(framesSent(0x06) + framesSent(0x10) - before, 1); // the priority write alone
}
