// A group write that cannot verify says so, and a group start says who follows, in the real
// window: drives 2 (DBU200) and 150 (DBU400) follow drive 1 (DBU200). A value drive 150 does not
// allow is refused naming it and its range before anything is sent; a child that ends up holding
// another value turns the write red, naming it; the start question names the child in I/O
// priority and the report after the start says who runs.
#include "tests/ui/main/MainWindowGroupsFixture.h"
#include "ui/workspace/MultiDriveWriteDialog.h"

#include <QLabel>

using namespace opentop;
using namespace opentop::test;

namespace {

const QString kSpno5 = QStringLiteral("spno5.speed");
constexpr quint16 kSpno5Address = 0xCA09;
const QString kRed = QStringLiteral("#b01c1c");

class MainWindowGroupVerifyTest : public MainWindowGroupsFixture
{
protected:
    // Drive 1's Running data page, shown, with its values read.
    ParameterPage* runningData()
    {
        select({1});
        if (!waitFor(
                [&] { return window->workspace()->drive() == window->drives()->parameters(1); }))
            return nullptr;
        ParameterPage* page = window->workspace()->page(QStringLiteral("Running data"));
        if (!page || !waitFor([&] { return deviceNumber(1, kSpno5) >= 0; }))
            return nullptr;
        window->workspace()->tabs()->setCurrentWidget(page); // in front, as the user edits it
        return page;
    }

    // The label showing the page's status line (red when something went wrong).
    QLabel* statusLabel(ParameterPage* page)
    {
        for (QLabel* l : page->findChildren<QLabel*>())
            if (l->text() == page->statusText() && !l->text().isEmpty())
                return l;
        return nullptr;
    }

    int framesTo(int slave, quint8 function)
    {
        int n = 0;
        for (const TrafficEntry& e : window->trafficLog()->entries())
            n += e.direction == TrafficEntry::Direction::Tx && e.slave == slave &&
                         e.function == function
                     ? 1
                     : 0;
        return n;
    }
};

} // namespace

TEST_F(MainWindowGroupVerifyTest, AValueAChildDoesNotAllowIsRefusedNamingItAndNothingIsSent)
{
    makeGroupOfOne();
    ParameterPage* page = runningData();
    ASSERT_NE(page, nullptr);
    const int on1 = simRegister(1, kSpno5Address);
    const int on2 = simRegister(2, kSpno5Address);
    const int on150 = simRegister(150, kSpno5Address);
    const int writes = framesTo(1, 6);
    // No group question may come: the value is refused before it.
    auto question = answer(QStringLiteral("groupWriteQuestion"), QString());

    ParameterField* speed = field(kSpno5);
    ASSERT_NE(speed, nullptr);
    speed->enter(QStringLiteral("280")); // a DBU200 allows it; the DBU400 (150) does not
    EXPECT_TRUE(speed->problem().contains(QStringLiteral("machine number 150 (DBU400-D4)")))
        << qPrintable(speed->problem());
    EXPECT_TRUE(speed->problem().contains(QStringLiteral("0 or 300–3000 r/min")))
        << qPrintable(speed->problem());
    // Shown on the grid's own message line, under the grid (it never moves the rows).
    auto* line = page->findChild<QLabel*>(QStringLiteral("fieldMessages"));
    ASSERT_NE(line, nullptr);
    EXPECT_TRUE(line->isVisible());
    EXPECT_TRUE(line->text().contains(QStringLiteral("machine number 150")))
        << qPrintable(line->text());
    page->writePage();
    EXPECT_TRUE(page->statusText().startsWith(QStringLiteral("Nothing was written")))
        << qPrintable(page->statusText());
    EXPECT_TRUE(page->statusText().contains(QStringLiteral("machine number 150")))
        << qPrintable(page->statusText());
    QTest::qWait(300);
    EXPECT_TRUE(question->isEmpty()) << qPrintable(*question);
    EXPECT_EQ(framesTo(1, 6), writes);
    EXPECT_EQ(simRegister(1, kSpno5Address), on1);
    EXPECT_EQ(simRegister(2, kSpno5Address), on2);
    EXPECT_EQ(simRegister(150, kSpno5Address), on150);

    // The multi-drive write to drive 1 alone refuses it too, naming the child.
    MultiDriveWriteDialog dialog(window->drives(), {1}, kSpno5, window.get());
    ASSERT_TRUE(waitFor([&] { return !dialog.busy(); }));
    dialog.setValueText(QStringLiteral("280"));
    EXPECT_TRUE(dialog.problem().contains(QStringLiteral("machine number 150")))
        << qPrintable(dialog.problem());
    EXPECT_EQ(simRegister(1, kSpno5Address), on1);
}

TEST_F(MainWindowGroupVerifyTest, AChildHoldingAnotherValueTurnsTheWriteRedAndNamesIt)
{
    makeGroupOfOne();
    // Drive 150 does not take what its parent is sent (the simulator's defect).
    ASSERT_TRUE(
        bus->control(150, {QStringLiteral("defect"), QStringLiteral("nostick=spno5.speed")}).ok);
    ParameterPage* page = runningData();
    ASSERT_NE(page, nullptr);
    const int on150 = simRegister(150, kSpno5Address);
    ASSERT_NE(on150, 1500);
    auto question = answer(QStringLiteral("groupWriteQuestion"), QStringLiteral("groupWriteYes"));
    ParameterField* speed = field(kSpno5);
    ASSERT_NE(speed, nullptr);
    speed->enter(QStringLiteral("1500"));
    page->writePage();
    ASSERT_TRUE(waitFor([&] { return !page->busy() && !question->isEmpty(); }));
    ASSERT_TRUE(waitFor([&] { return !page->statusText().startsWith(QStringLiteral("Writing")); }));
    EXPECT_EQ(simRegister(1, kSpno5Address), 1500);
    EXPECT_EQ(simRegister(2, kSpno5Address), 1500);
    EXPECT_EQ(simRegister(150, kSpno5Address), on150);
    // Never "verified": the page's status is red and names the child and what it holds.
    const QString status = page->statusText();
    EXPECT_FALSE(status.contains(QStringLiteral("verified"))) << qPrintable(status);
    const QString holds =
        QStringLiteral("machine number 150 holds %1 r/min, not 1500 r/min").arg(on150);
    EXPECT_TRUE(status.contains(holds)) << qPrintable(status);
    QLabel* label = statusLabel(page);
    ASSERT_NE(label, nullptr);
    EXPECT_TRUE(label->styleSheet().contains(kRed));
    // The field too: red, with the same words under it.
    EXPECT_EQ(window->drives()->parameters(1)->entry(kSpno5)->state,
              DeviceParameters::State::Failed);
    EXPECT_TRUE(speed->messageLabel()->text().contains(holds))
        << qPrintable(speed->messageLabel()->text());
    // The child's page shows what it holds: read from it.
    EXPECT_EQ(deviceNumber(150, kSpno5), on150);

    // The multi-drive dialog says it in its result too.
    answer(QStringLiteral("groupWriteQuestion"), QStringLiteral("groupWriteYes"));
    MultiDriveWriteDialog dialog(window->drives(), {1}, kSpno5, window.get());
    ASSERT_TRUE(waitFor([&] { return !dialog.busy(); }));
    dialog.setValueText(QStringLiteral("1400"));
    int failed = -1;
    QObject::connect(&dialog, &MultiDriveWriteDialog::writeFinished, [&](int f) { failed = f; });
    dialog.writeToAll();
    ASSERT_TRUE(waitFor([&] { return failed >= 0; }));
    EXPECT_EQ(failed, 1);
    EXPECT_TRUE(dialog.cellText(1, MultiDriveWriteDialog::Result)
                    .contains(QStringLiteral("machine number 150 holds")))
        << qPrintable(dialog.cellText(1, MultiDriveWriteDialog::Result));
}

TEST_F(MainWindowGroupVerifyTest, TheStartQuestionNamesTheChildInIoPriorityAndTheReportWhoRuns)
{
    makeGroupOfOne();
    // 1 and 2 take run commands over the bus; 150 is in I/O priority.
    for (int slave : {1, 2})
        bus->control(slave, {QStringLiteral("set"), QStringLiteral("0x100D"), QStringLiteral("2")});
    select({1});
    TestRunPanel* panel = showTestRun(*window, 1);
    ASSERT_TRUE(panel);
    ASSERT_TRUE(waitFor([&] { return panel->commandsEnabled(); }));
    bool finished = false;
    QObject::connect(panel, &TestRunPanel::commandFinished, [&](bool) { finished = true; });
    const QString question = clickAndConfirm(panel, QStringLiteral("start"));
    EXPECT_TRUE(question.contains(QStringLiteral("Machine number 150 does NOT follow it: it is in "
                                                 "I/O priority")))
        << qPrintable(question);
    EXPECT_TRUE(question.contains(QStringLiteral("Machine number 2 follows it")))
        << qPrintable(question);
    ASSERT_TRUE(waitFor([&] { return finished; }));
    ASSERT_TRUE(waitFor([&] { return speedOf(2) > 0; }));
    EXPECT_EQ(speedOf(150), 0);
    const QString report = panel->stateText();
    EXPECT_TRUE(report.contains(QStringLiteral("Machine number 2 runs"))) << qPrintable(report);
    EXPECT_TRUE(report.contains(QStringLiteral("Machine number 150 does not run: it is in I/O "
                                               "priority")))
        << qPrintable(report);
    // Its E2h is explained in words, with what to do.
    EXPECT_TRUE(report.contains(QStringLiteral("E2h Cannot execute command: ")))
        << qPrintable(report);
    EXPECT_TRUE(report.contains(QStringLiteral("set Control priority (Core parameters) to "
                                               "Communication priority")))
        << qPrintable(report);
    EXPECT_TRUE(panel->messageText().contains(QStringLiteral("Not every drive")))
        << qPrintable(panel->messageText());
    // Drive 150 holds that code (read from it), the one the report explained.
    ASSERT_TRUE(
        waitFor([&] { return deviceNumber(150, QStringLiteral("status.comm_error")) > 0; }));
    EXPECT_EQ(deviceNumber(150, QStringLiteral("status.comm_error")), 0xE2);
    select({1});
    ASSERT_TRUE(
        waitFor([&] { return window->workspace()->drive() == window->drives()->parameters(1); }));
    panel = showTestRun(*window, 1);
    ASSERT_TRUE(panel);
    // Stopped again (the fixture's window leaves nothing running).
    QPushButton* stop = panel->findChild<QPushButton*>(QStringLiteral("stop"));
    ASSERT_TRUE(waitFor([&] { return stop->isEnabled() && stop->isVisible(); }))
        << "enabled " << stop->isEnabled() << " visible " << stop->isVisible();
    stop->click();
    EXPECT_TRUE(waitFor([&] { return speedOf(1) == 0 && speedOf(2) == 0; }));
}
