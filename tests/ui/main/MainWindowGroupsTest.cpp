// Communication groups in the real window: a write to a group parent names the drives it also
// reaches before anything is sent and reads their values back afterwards; the group view shows
// who follows whom, flags what is wrong, and writes a plan proved by reading every drive back.
#include "model/bus/BusGroupTracker.h"
#include "tests/ui/main/MainWindowGroupsFixture.h"
#include "ui/alarms/AlarmsPage.h"
#include "ui/groups/GroupsView.h"
#include "ui/workspace/MultiDriveWriteDialog.h"
#include "ui/workspace/ParameterInitBox.h"

using namespace opentop;
using namespace opentop::test;

namespace {

using MainWindowGroupsTest = MainWindowGroupsFixture;

const QString kSpeed = QStringLiteral("spno2.speed");
constexpr quint16 kSpeedAddress = 0xCA03;

} // namespace

TEST_F(MainWindowGroupsTest, APageWriteToAParentNamesItsChildrenFirstAndReadsTheirValuesBack)
{
    // The groups are known once identified; the view shows who follows whom.
    ASSERT_TRUE(waitFor([&] { return window->groups()->isKnown(1); }));
    EXPECT_TRUE(window->groups()->groups().childrenOf(1).isEmpty());
    makeGroupOfOne();
    EXPECT_EQ(window->groupsView()->cellText(1, GroupsView::Role),
              QStringLiteral("parent of 2, 150"));
    EXPECT_EQ(window->groupsView()->cellText(150, GroupsView::Role), QStringLiteral("child of 1"));

    select({1});
    ASSERT_TRUE(waitFor([&] { return window->workspace()->drive() != nullptr; }));
    ParameterPage* page = window->workspace()->page(QStringLiteral("Running data"));
    ASSERT_NE(page, nullptr);
    ASSERT_TRUE(waitFor([&] { return deviceNumber(1, kSpeed) >= 0; }));
    const int before = simRegister(1, kSpeedAddress);
    ASSERT_NE(before, 2345);
    ASSERT_NE(deviceNumber(2, kSpeed), 2345);
    ASSERT_NE(deviceNumber(150, kSpeed), 2345);
    const int framesBefore = int(window->trafficLog()->entries().size());

    int onDriveWhileAsked = -1;
    auto question = answer(QStringLiteral("groupWriteQuestion"), QStringLiteral("groupWriteYes"),
                           [&] { onDriveWhileAsked = simRegister(1, kSpeedAddress); });
    ParameterField* speed = field(kSpeed);
    ASSERT_NE(speed, nullptr);
    speed->enter(QStringLiteral("2345"));
    page->writePage();
    ASSERT_TRUE(waitFor([&] { return !window->drives()->parameters(1)->hasPending(); }));
    // Asked before sending, naming the children.
    EXPECT_TRUE(question->contains(QStringLiteral("machine numbers 2 and 150")))
        << qPrintable(*question);
    EXPECT_EQ(onDriveWhileAsked, before);
    EXPECT_EQ(simRegister(1, kSpeedAddress), 2345);
    // The children executed it and their values were read from them, not assumed.
    EXPECT_EQ(simRegister(150, kSpeedAddress), 2345);
    EXPECT_TRUE(waitFor(
        [&] { return deviceNumber(2, kSpeed) == 2345 && deviceNumber(150, kSpeed) == 2345; }));
    bool readFromChild = false;
    bool describedAsGroupWrite = false;
    const auto entries = window->trafficLog()->entries();
    for (int i = framesBefore; i < entries.size(); ++i) {
        const TrafficEntry& e = entries.at(i);
        readFromChild =
            readFromChild || (e.direction == TrafficEntry::Direction::Tx && e.slave == 150 &&
                              e.function == 3 && e.summary.contains(QStringLiteral("0xCA03")));
        describedAsGroupWrite = describedAsGroupWrite ||
                                e.summary.contains(QStringLiteral("group parent: also 2, 150"));
    }
    EXPECT_TRUE(readFromChild);
    EXPECT_TRUE(describedAsGroupWrite); // the traffic log says who else the write reached
}

TEST_F(MainWindowGroupsTest, CancellingTheGroupQuestionSendsNothing)
{
    makeGroupOfOne();
    select({1});
    ASSERT_TRUE(waitFor([&] { return window->workspace()->drive() != nullptr; }));
    ASSERT_TRUE(waitFor([&] { return deviceNumber(1, kSpeed) >= 0; }));
    const int before = simRegister(1, kSpeedAddress);
    const int childBefore = simRegister(2, kSpeedAddress);
    auto question = answer(QStringLiteral("groupWriteQuestion"), QString());
    ParameterField* speed = field(kSpeed);
    ASSERT_NE(speed, nullptr);
    speed->enter(QStringLiteral("2345"));
    window->workspace()->writeAll(); // the Drive menu's "Write all pending"
    ASSERT_TRUE(waitFor([&] { return !question->isEmpty(); }));
    EXPECT_TRUE(question->contains(QStringLiteral("2 and 150")));
    QTest::qWait(200);
    EXPECT_EQ(simRegister(1, kSpeedAddress), before);
    EXPECT_EQ(simRegister(2, kSpeedAddress), childBefore);
    EXPECT_TRUE(window->drives()->parameters(1)->hasPending()); // the edit stays
}

TEST_F(MainWindowGroupsTest, TheMultiDriveWriteNamesTheChildrenAndTheirValuesAreReadBack)
{
    makeGroupOfOne();
    auto question = answer(QStringLiteral("groupWriteQuestion"), QStringLiteral("groupWriteYes"));
    MultiDriveWriteDialog dialog(window->drives(), {1}, kSpeed, window.get());
    ASSERT_TRUE(waitFor([&] { return !dialog.busy(); }));
    dialog.setValueText(QStringLiteral("1555"));
    int failed = -1;
    QObject::connect(&dialog, &MultiDriveWriteDialog::writeFinished, [&](int f) { failed = f; });
    dialog.writeToAll();
    ASSERT_TRUE(waitFor([&] { return failed >= 0; }));
    EXPECT_EQ(failed, 0);
    EXPECT_TRUE(question->contains(QStringLiteral("2 and 150")));
    EXPECT_TRUE(waitFor(
        [&] { return deviceNumber(2, kSpeed) == 1555 && deviceNumber(150, kSpeed) == 1555; }));
}

TEST_F(MainWindowGroupsTest, TheGroupViewFlagsAChainAndAGroupNumberNoDriveHas)
{
    setGroupInSimulator(2, 1);   // 2 follows 1
    setGroupInSimulator(150, 2); // 150 follows 2: 2 is child and parent
    setGroupInSimulator(1, 99);  // 1 follows 99: no such drive
    readGroups();
    GroupsView* view = window->groupsView();
    EXPECT_EQ(view->cellText(2, GroupsView::Problem), QStringLiteral("child and parent"));
    EXPECT_EQ(view->cellText(1, GroupsView::Problem), QStringLiteral("no drive 99"));
    EXPECT_TRUE(view->cellText(150, GroupsView::Problem).isEmpty());
    EXPECT_TRUE(view->problemsText().contains(
        QStringLiteral("machine number 2 is a child of 1 and itself a parent")));
    EXPECT_TRUE(view->problemsText().contains(QStringLiteral("no drive 99 is known")));
    // Fixed in the simulator and read again: no problem left.
    setGroupInSimulator(150, 0xFFFF);
    setGroupInSimulator(1, 0xFFFF);
    readGroups();
    EXPECT_TRUE(view->cellText(2, GroupsView::Problem).isEmpty());
    EXPECT_TRUE(view->problemsText().startsWith(QStringLiteral("No problem")));
}

TEST_F(MainWindowGroupsTest, AGroupPlanIsWrittenAndProvedByReadingEveryDriveBack)
{
    ASSERT_TRUE(waitFor([&] { return window->groups()->isKnown(150); }));
    GroupsView* view = window->groupsView();
    // Reachable from the Bus menu.
    QAction* open = nullptr;
    for (QAction* a : window->findChildren<QAction*>())
        open = a->text() == QStringLiteral("Communication &groups…") ? a : open;
    ASSERT_NE(open, nullptr);
    open->trigger();
    EXPECT_TRUE(view->isVisible());
    view->setPlanned(2, 1);
    view->setPlanned(150, 1);
    auto question = answer(QStringLiteral("groupPlanQuestion"), QStringLiteral("groupPlanYes"));
    bool proved = false;
    bool finished = false;
    QObject::connect(view, &GroupsView::planFinished, [&](bool p) {
        proved = p;
        finished = true;
    });
    view->writePlan();
    ASSERT_TRUE(waitFor([&] { return finished; }));
    EXPECT_TRUE(proved) << qPrintable(view->resultText());
    EXPECT_TRUE(question->contains(QStringLiteral("Machine number 2: group Disabled → 1")));
    EXPECT_EQ(simRegister(2, 0x00F5), 1);
    EXPECT_EQ(simRegister(150, 0x00F5), 1);
    EXPECT_EQ(window->groups()->groups().childrenOf(1), (QVector<int>{2, 150}));
    EXPECT_TRUE(view->cellText(150, GroupsView::Result).startsWith(QStringLiteral("✓")));

    // Then drive 1 leaves its own group disabled but 2 is to follow 150 instead: the write to
    // 2 reaches nobody, 150 keeps following 1. Proved again by reading back.
    finished = false;
    view->setPlanned(2, 150);
    view->setPlanned(150, 0);
    answer(QStringLiteral("groupPlanQuestion"), QStringLiteral("groupPlanYes"));
    view->writePlan();
    ASSERT_TRUE(waitFor([&] { return finished; }));
    EXPECT_TRUE(proved) << qPrintable(view->resultText());
    EXPECT_EQ(simRegister(2, 0x00F5), 150);
    EXPECT_EQ(simRegister(150, 0x00F5), 0xFFFF);
    EXPECT_EQ(window->groups()->groups().childrenOf(150), QVector<int>{2});
}

TEST_F(MainWindowGroupsTest, AnAlarmResetToAParentNamesItsChildrenInItsQuestion)
{
    makeGroupOfOne();
    select({1});
    ASSERT_TRUE(waitFor([&] { return window->workspace()->drive() != nullptr; }));
    AlarmsPage* alarms = nullptr;
    for (int i = 0; i < window->workspace()->tabs()->count(); ++i)
        alarms =
            alarms ? alarms : qobject_cast<AlarmsPage*>(window->workspace()->tabs()->widget(i));
    ASSERT_NE(alarms, nullptr);
    ASSERT_TRUE(waitFor([&] { return !alarms->isBusy(); }));
    const int framesBefore = int(window->trafficLog()->entries().size());
    alarms->resetAlarm();
    QMessageBox* box = nullptr;
    ASSERT_TRUE(waitFor([&] {
        box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        return box != nullptr;
    }));
    EXPECT_TRUE(box->informativeText().contains(QStringLiteral("machine numbers 2 and 150")))
        << qPrintable(box->informativeText());
    box->button(QMessageBox::Cancel)->click();
    QTest::qWait(100);
    const auto entries = window->trafficLog()->entries();
    for (int i = framesBefore; i < entries.size(); ++i)
        EXPECT_NE(entries.at(i).function, 6) << qPrintable(entries.at(i).summary); // no write
}

TEST_F(MainWindowGroupsTest, AnInitialisationOfAParentNamesItsChildrenAndReReadsThem)
{
    makeGroupOfOne();
    bus->control(150, {QStringLiteral("set"), QStringLiteral("0xCA03"), QStringLiteral("2200")});
    DeviceParameters* child = window->drives()->parameters(150);
    bool read = false;
    child->refresh({kSpeed}, [&](int) { read = true; });
    ASSERT_TRUE(waitFor([&] { return read; }));
    ASSERT_EQ(deviceNumber(150, kSpeed), 2200);
    select({1});
    ASSERT_TRUE(waitFor([&] { return window->workspace()->drive() != nullptr; }));
    ParameterInitBox* init = nullptr;
    for (int i = 0; i < window->workspace()->tabs()->count() && !init; ++i) {
        auto* page = qobject_cast<ParameterPage*>(window->workspace()->tabs()->widget(i));
        if (page && page->parameterNames().contains(QStringLiteral("comm.rate"))) {
            window->workspace()->tabs()->setCurrentWidget(page);
            init = page->findChild<ParameterInitBox*>();
        }
    }
    ASSERT_NE(init, nullptr);
    bool finished = false;
    QObject::connect(init, &ParameterInitBox::finished, init, [&] { finished = true; });
    init->start();
    QMessageBox* box = nullptr;
    ASSERT_TRUE(waitFor([&] {
        box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        return box != nullptr;
    }));
    const QString text = box->informativeText();
    EXPECT_TRUE(text.contains(QStringLiteral("machine numbers 2 and 150"))) << qPrintable(text);
    EXPECT_FALSE(text.contains(QStringLiteral("only"))) << qPrintable(text);
    box->button(QMessageBox::Yes)->click();
    ASSERT_TRUE(waitFor([&] { return finished; }, 20000));
    // The child executed it too; its value on screen is the one read from it afterwards.
    EXPECT_EQ(simRegister(150, kSpeedAddress), 1000);
    EXPECT_TRUE(waitFor([&] { return deviceNumber(150, kSpeed) == 1000; }));
}

TEST_F(MainWindowGroupsTest, SwitchingAParentToCommunicationPriorityNamesItsChildren)
{
    makeGroupOfOne();
    select({1});
    ASSERT_TRUE(
        waitFor([&] { return window->workspace()->drive() == window->drives()->parameters(1); }));
    QTabWidget* tabs = window->workspace()->tabs();
    QPushButton* button = nullptr;
    ASSERT_TRUE(waitFor([&] {
        for (int i = 0; i < tabs->count(); ++i) {
            if (auto* b =
                    tabs->widget(i)->findChild<QPushButton*>(QStringLiteral("switchPriority"))) {
                tabs->setCurrentIndex(i);
                button = b;
            }
        }
        return button && button->isVisible() && button->isEnabled();
    }));
    const int before = simRegister(1, 0x100D);
    button->click();
    QMessageBox* box = nullptr;
    ASSERT_TRUE(waitFor([&] {
        box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        return box != nullptr;
    }));
    const QString text = box->text() + QLatin1Char('\n') + box->informativeText();
    box->button(QMessageBox::Cancel)->click();
    EXPECT_TRUE(text.contains(QStringLiteral("2 and 150"))) << qPrintable(text);
    QTest::qWait(300);
    EXPECT_EQ(simRegister(1, 0x100D), before); // cancelled: nothing sent
}
