// What the exit question offers and says for each mix of drives left behind (issue 24 item 6):
// the default stops and gives back, a family without I/O priority is stopped only, and each
// drive's line says what will happen to it.
#include "model/run/ExitPlan.h"

#include <gtest/gtest.h>

using namespace opentop;

namespace {

DriveLeftBehind drive(int slave, const QString& model, bool running, bool busPriority,
                      bool canReturn)
{
    DriveLeftBehind d;
    d.slave = slave;
    d.model = model;
    d.running = running;
    d.busPriority = busPriority;
    d.canReturn = canReturn;
    d.state = running ? QStringLiteral("Running CW") : QStringLiteral("Stopped, no alarm");
    return d;
}

using Choice = ExitPlan::Choice;

} // namespace

TEST(ExitPlanTest, ARunningDriveInCommunicationPriorityIsStoppedThenGivenBackByDefault)
{
    const ExitPlan plan({drive(1, QStringLiteral("DBU200-D"), true, true, true),
                         drive(2, QStringLiteral("DBU200-D"), false, true, true)});
    EXPECT_EQ(plan.running(), QVector<int>{1});
    EXPECT_EQ(plan.returnable(), (QVector<int>{1, 2}));
    EXPECT_EQ(plan.choices(),
              (QVector<Choice>{Choice::StopAndGiveBack, Choice::GiveBackOnly, Choice::Leave}));
    EXPECT_EQ(plan.label(Choice::StopAndGiveBack), QStringLiteral("Stop and give control back"));
    EXPECT_EQ(plan.label(Choice::Leave), QStringLiteral("Leave them running"));
    const QStringList lines = plan.lines();
    ASSERT_EQ(lines.size(), 2);
    EXPECT_TRUE(lines[0].startsWith(QStringLiteral("• Machine number 1 (DBU200-D): Running CW")));
    EXPECT_TRUE(lines[0].contains(QStringLiteral("→ stopped (confirmed by reading it), then given "
                                                 "back to its own inputs")))
        << qPrintable(lines[0]);
    EXPECT_TRUE(lines[1].contains(QStringLiteral("→ given back to its own inputs")))
        << qPrintable(lines[1]);
    EXPECT_EQ(plan.actionText(Choice::StopAndGiveBack),
              QStringLiteral("stop and give control back to"));
    EXPECT_TRUE(plan.explanation().contains(QStringLiteral("Give control back only")));
}

TEST(ExitPlanTest, ADcControllerIsStoppedOnlyAndTheQuestionSaysWhy)
{
    const ExitPlan plan({drive(7, QStringLiteral("DC PID"), true, false, false)});
    EXPECT_EQ(plan.running(), QVector<int>{7});
    EXPECT_TRUE(plan.returnable().isEmpty());
    // Nothing to give back: no "give control back only", and the default is a stop.
    EXPECT_EQ(plan.choices(), (QVector<Choice>{Choice::StopAndGiveBack, Choice::Leave}));
    EXPECT_EQ(plan.label(Choice::StopAndGiveBack), QStringLiteral("Stop the drives"));
    EXPECT_EQ(plan.actionText(Choice::StopAndGiveBack), QStringLiteral("stop"));
    EXPECT_TRUE(plan.lines().first().contains(QStringLiteral("no I/O priority setting")))
        << qPrintable(plan.lines().first());
    EXPECT_FALSE(plan.explanation().contains(QStringLiteral("Give control back")));
}

TEST(ExitPlanTest, DrivesOnlyInCommunicationPriorityAreGivenBack)
{
    const ExitPlan plan({drive(2, QStringLiteral("DBU200-D"), false, true, true)});
    EXPECT_TRUE(plan.running().isEmpty());
    EXPECT_EQ(plan.choices(), (QVector<Choice>{Choice::StopAndGiveBack, Choice::Leave}));
    EXPECT_EQ(plan.label(Choice::StopAndGiveBack),
              QStringLiteral("Give control back (I/O priority)"));
    EXPECT_EQ(plan.label(Choice::Leave), QStringLiteral("Leave them so"));
    EXPECT_EQ(plan.title(), QStringLiteral("Drives left in communication priority"));
}

TEST(ExitPlanTest, NothingLeftBehindAsksNothing)
{
    const ExitPlan plan;
    EXPECT_TRUE(plan.isEmpty());
    EXPECT_EQ(plan.choices(), QVector<Choice>{Choice::Leave});
}

TEST(ExitPlanTest, ADriveRunningFromItsInputsIsNamedAndLeftToThem)
{
    DriveLeftBehind fromInputs = drive(3, QStringLiteral("DBU400-D4"), true, false, true);
    fromInputs.inputsControl = true;
    const ExitPlan plan({fromInputs});
    EXPECT_TRUE(plan.running().isEmpty()); // a stop over the bus would be refused
    EXPECT_TRUE(plan.anyRunning());
    EXPECT_EQ(plan.title(), QStringLiteral("Drives are running"));
    EXPECT_EQ(plan.choices(), QVector<Choice>{Choice::Leave});
    EXPECT_EQ(plan.label(Choice::Leave), QStringLiteral("Leave them running"));
    EXPECT_TRUE(plan.lines().first().contains(QStringLiteral("runs from its own inputs")))
        << qPrintable(plan.lines().first());
}
