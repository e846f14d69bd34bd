// The Test run page in the real window: live state with its age, the start question, the way
// back to I/O priority, the trend of a run started there, and the DC controller's pages.
#include "tests/ui/main/MainWindowFixture.h"

#include "model/session/Freshness.h"
#include "sim/FaultInjector.h"
#include "ui/pages/DcControllerPage.h"
#include "ui/pages/RunningDataPage.h"
#include "ui/run/RunLiveState.h"
#include "ui/run/SpnoSelector.h"
#include "ui/trends/TrendChart.h"

#include <QChart>
#include <QComboBox>
#include <QLineEdit>
#include <QLineSeries>

using MainWindowRunTest = opentop::test::MainWindowFixture;

namespace opentop::test {
namespace {

// The drive's page of type T among the current tabs (pages of a drive shown before may still
// await deletion).
template <typename T> T* pageOf(MainWindow& window, int slave)
{
    if (window.workspace()->drive() != window.drives()->parameters(slave))
        return nullptr;
    QTabWidget* tabs = window.workspace()->tabs();
    for (int i = 0; i < tabs->count(); ++i) {
        if (auto* page = qobject_cast<T*>(tabs->widget(i)))
            return page;
        if (auto* page = tabs->widget(i)->findChild<T*>())
            return page;
    }
    return nullptr;
}

// Makes the tab holding `page` current (pages read their values when shown).
void showPage(MainWindow& window, QWidget* page)
{
    QTabWidget* tabs = window.workspace()->tabs();
    for (int i = 0; i < tabs->count(); ++i) {
        if (tabs->widget(i) == page || tabs->widget(i)->isAncestorOf(page))
            tabs->setCurrentIndex(i);
    }
}

} // namespace
} // namespace opentop::test

using namespace opentop::test;

TEST_F(MainWindowRunTest, ARunStartedFromTheTestRunPageIsInTheDrivesTrend)
{
    bus->control(1, {QStringLiteral("set"), QStringLiteral("0x100D"), QStringLiteral("2")});
    select({1});
    TestRunPanel* panel = showTestRun(*window, 1);
    ASSERT_TRUE(panel);
    ASSERT_TRUE(panel->liveState());
    // The Monitor page is in the background: the Test run page is what watches the drive.
    ASSERT_TRUE(waitFor([&] { return panel->commandsEnabled(); }));
    EXPECT_TRUE(window->monitorHub()->isWatched(1));
    clickAndConfirm(panel, QStringLiteral("start"));
    ASSERT_TRUE(waitFor([&] { return speedOf(1) > 0; }));
    ASSERT_TRUE(waitFor([&] {
        const TrendHistory* h = window->monitorHub()->history(1);
        const TrendHistory::Series* s =
            h ? h->find(QStringLiteral("status.current_speed")) : nullptr;
        return s && !s->points.isEmpty() && s->points.last().value > 0;
    }));
    // A settings page (no live values): nothing watches the drive any more.
    QTabWidget* tabs = window->workspace()->tabs();
    for (int i = 0; i < tabs->count(); ++i) {
        if (tabs->tabText(i).remove(QLatin1Char('&')).contains(QStringLiteral("Core parameters")))
            tabs->setCurrentIndex(i);
    }
    ASSERT_TRUE(tabs->tabText(tabs->currentIndex()).contains(QStringLiteral("Core")));
    EXPECT_TRUE(waitFor([&] { return !window->monitorHub()->isWatched(1); }));
}

TEST_F(MainWindowRunTest, APollingGapIsAGapInTheTrendChart)
{
    MonitorHub* hub = window->monitorHub();
    TrendChart chart(hub);
    chart.resize(900, 500);
    chart.setSources({{1, QStringLiteral("status.current_speed")}});
    chart.show();
    select({1});
    ASSERT_TRUE(showTestRun(*window, 1));
    auto pointCount = [&] {
        const TrendHistory::Series* s =
            hub->history(1) ? hub->history(1)->find(QStringLiteral("status.current_speed"))
                            : nullptr;
        return s ? int(s->points.size()) : 0;
    };
    ASSERT_TRUE(waitFor([&] { return pointCount() >= 3; }));
    chart.refresh();
    auto drawnSegments = [&] {
        int n = 0;
        for (const QList<QPointF>& part : chart.lines().lines().value(0).drawn)
            n += part.isEmpty() ? 0 : 1;
        return n;
    };
    EXPECT_EQ(drawnSegments(), 1);
    // Polling stops for longer than a value stays live, then goes on.
    hub->setPaused(true);
    QTest::qWait(int(Freshness::staleAfterMs(hub->interval())) + 800);
    const int before = pointCount();
    hub->setPaused(false);
    ASSERT_TRUE(waitFor([&] { return pointCount() >= before + 3; }));
    chart.refresh();
    EXPECT_EQ(drawnSegments(), 2);
    // No segment spans the gap.
    for (const QList<QPointF>& points : chart.lines().lines().value(0).drawn) {
        for (int i = 1; i < points.size(); ++i)
            EXPECT_LE(points[i].x() - points[i - 1].x(),
                      double(Freshness::staleAfterMs(hub->interval())));
    }
}

TEST_F(MainWindowRunTest, TheStartQuestionSaysWhichSpnoSpeedDirectionAndGroupDrivesRun)
{
    bus->control(1, {QStringLiteral("set"), QStringLiteral("0x100D"), QStringLiteral("2")});
    bus->control(1, {QStringLiteral("set"), QStringLiteral("0x200F"), QStringLiteral("2")});
    bus->control(1, {QStringLiteral("set"), QStringLiteral("0xCA05"), QStringLiteral("1700")});
    bus->control(1, {QStringLiteral("set"), QStringLiteral("0x0315"), QStringLiteral("1")});
    bus->control(1, {QStringLiteral("set"), QStringLiteral("0x4505"), QStringLiteral("5")});
    // Drive 2 follows drive 1 (communication group 1).
    bus->control(2, {QStringLiteral("set"), QStringLiteral("0x00F5"), QStringLiteral("1")});
    select({1});
    TestRunPanel* panel = showTestRun(*window, 1);
    ASSERT_TRUE(panel);
    ASSERT_TRUE(waitFor([&] { return panel->commandsEnabled(); }));
    const QString text = clickAndConfirm(panel, QStringLiteral("start"));
    EXPECT_TRUE(text.contains(QStringLiteral("SPno3"))) << qPrintable(text);
    EXPECT_TRUE(text.contains(QStringLiteral("1700 r/min"))) << qPrintable(text);
    EXPECT_TRUE(text.contains(QStringLiteral("direction CCW"))) << qPrintable(text);
    EXPECT_TRUE(text.contains(QStringLiteral("also executed by 2"))) << qPrintable(text);
    EXPECT_TRUE(text.contains(QStringLiteral("deceleration time"))) << qPrintable(text);
    ASSERT_TRUE(waitFor([&] { return speedOf(1) > 0; }));
    // A start that reaches other drives is asked every time, not once per drive.
    panel->findChild<QPushButton*>(QStringLiteral("stop"))->click();
    ASSERT_TRUE(waitFor([&] { return speedOf(1) == 0; }, 15000));
    ASSERT_TRUE(waitFor(
        [&] { return panel->findChild<QPushButton*>(QStringLiteral("start"))->isEnabled(); }));
    EXPECT_FALSE(clickAndConfirm(panel, QStringLiteral("start")).isEmpty());
}

TEST_F(MainWindowRunTest, TheTestRunPageSpeedFollowsTheDriveAndGreysWhenTheLinkIsLost)
{
    bus->control(1, {QStringLiteral("vr"), QStringLiteral("3000")});
    select({1});
    TestRunPanel* panel = showTestRun(*window, 1);
    ASSERT_TRUE(panel);
    RunLiveState* live = panel->liveState();
    ASSERT_TRUE(live);
    ASSERT_TRUE(waitFor([&] { return !live->speedText().isEmpty() && !live->isStale(); }));
    EXPECT_EQ(live->stateText(), QStringLiteral("Stopped"));
    startDrive(1);
    // The shown speed follows the drive over its ramp: several different values, each close
    // to what the drive ran at the time.
    QSet<QString> seen;
    for (int i = 0; i < 12; ++i) {
        QTest::qWait(150);
        seen.insert(live->speedText());
    }
    EXPECT_GE(seen.size(), 3);
    ASSERT_TRUE(waitFor([&] { return speedOf(1) >= 2900; }, 8000));
    ASSERT_TRUE(waitFor([&] { return live->speedText().startsWith(QStringLiteral("3000")); }));
    EXPECT_TRUE(live->stateText().startsWith(QStringLiteral("Running")));
    EXPECT_TRUE(
        live->ageText(QStringLiteral("status.current_speed")).endsWith(QStringLiteral("old")));
    EXPECT_FALSE(live->isStale());

    // The link goes: grey, with the time of the last answer.
    FaultRates rates;
    rates.drop = 1.0;
    bus->setFaults(FaultInjector(rates));
    ASSERT_TRUE(waitFor([&] { return live->isStale(); }));
    EXPECT_TRUE(live->ageText(QStringLiteral("status.current_speed"))
                    .startsWith(QStringLiteral("last answer")));
    auto* value = live->findChild<QLabel*>(QStringLiteral("live_status.current_speed"));
    ASSERT_TRUE(value);
    EXPECT_TRUE(value->styleSheet().contains(QStringLiteral("#808080")));
    bus->setFaults(FaultInjector());
    EXPECT_TRUE(waitFor([&] { return !live->isStale(); }));
}

TEST_F(MainWindowRunTest, TheDcTestRunPageShowsStoppedAfterStopAll)
{
    select({7});
    TestRunPanel* panel = showTestRun(*window, 7);
    ASSERT_TRUE(panel);
    RunLiveState* live = panel->liveState();
    ASSERT_TRUE(live);
    ASSERT_TRUE(waitFor([&] { return panel->commandsEnabled(); }));
    panel->findChild<QLineEdit*>(QStringLiteral("speed"))->setText(QStringLiteral("30"));
    clickAndConfirm(panel, QStringLiteral("setSpeed"));
    ASSERT_TRUE(waitFor([&] { return live->stateText().startsWith(QStringLiteral("Running")); }))
        << qPrintable(live->stateText());
    EXPECT_TRUE(live->stateText().contains(QStringLiteral("%"))) << qPrintable(live->stateText());
    window->stopAllButton()->stopAll();
    ASSERT_TRUE(waitFor([&] { return live->stateText() == QStringLiteral("Stopped"); }, 15000))
        << qPrintable(live->stateText());
    EXPECT_FALSE(live->isStale());
    if (QMessageBox* result = window->stopAllButton()->resultWindow())
        result->close();
}

TEST_F(MainWindowRunTest, TheSpnoSelectorShowsEachSpnosSpeedAndDirection)
{
    bus->control(1, {QStringLiteral("set"), QStringLiteral("0xCA05"), QStringLiteral("1700")});
    bus->control(1, {QStringLiteral("set"), QStringLiteral("0x0315"), QStringLiteral("1")});
    select({1});
    TestRunPanel* panel = showTestRun(*window, 1);
    ASSERT_TRUE(panel);
    SpnoSelector* spno = panel->spnoSelector();
    ASSERT_TRUE(spno);
    ASSERT_TRUE(waitFor([&] { return spno->itemText(2).contains(QStringLiteral("r/min")); }));
    EXPECT_EQ(spno->itemText(2), QStringLiteral("SPno3 — 1700 r/min, CCW"));
    EXPECT_TRUE(spno->itemText(1).endsWith(QStringLiteral(", CW")))
        << qPrintable(spno->itemText(1));
}

TEST_F(MainWindowRunTest, TheTestRunPageGoesBackToIoPriority)
{
    bus->control(1, {QStringLiteral("set"), QStringLiteral("0x100D"), QStringLiteral("2")});
    select({1});
    TestRunPanel* panel = showTestRun(*window, 1);
    ASSERT_TRUE(panel);
    ASSERT_TRUE(waitFor([&] { return panel->commandsEnabled(); }));
    const QString question = clickAndConfirm(panel, QStringLiteral("ioPriority"));
    EXPECT_TRUE(question.contains(QStringLiteral("input terminals"))) << qPrintable(question);
    ASSERT_TRUE(waitFor([&] { return simRegister(1, 0x100D) == 1; }));
    EXPECT_TRUE(waitFor([&] { return !panel->commandsEnabled(); }));
}

TEST_F(MainWindowRunTest, TheDcControllerPageNotesACommunicationLossStopThatIsOff)
{
    bus->control(7, {QStringLiteral("set"), QStringLiteral("0x008E"), QStringLiteral("0")});
    select({7});
    DcControllerPage* page = nullptr;
    ASSERT_TRUE(waitFor([&] { return (page = pageOf<DcControllerPage>(*window, 7)); }));
    showPage(*window, page);
    ASSERT_TRUE(waitFor([&] { return !page->commLossNote().isEmpty(); }));
    EXPECT_TRUE(page->commLossNote().contains(QStringLiteral("keeps it running")));
    bus->control(7, {QStringLiteral("set"), QStringLiteral("0x008E"), QStringLiteral("20")});
    window->workspace()->refreshAll();
    EXPECT_TRUE(waitFor([&] { return page->commLossNote().isEmpty(); }));
}

TEST_F(MainWindowRunTest, TheRunningDataPageWarnsOfAShortDecelerationFromHighSpeed)
{
    bus->control(1, {QStringLiteral("set"), QStringLiteral("0xCA05"), QStringLiteral("2500")});
    bus->control(1, {QStringLiteral("set"), QStringLiteral("0x4505"), QStringLiteral("5")});
    select({1});
    RunningDataPage* page = nullptr;
    ASSERT_TRUE(waitFor([&] { return (page = pageOf<RunningDataPage>(*window, 1)); }));
    showPage(*window, page);
    ASSERT_TRUE(waitFor([&] {
        const QString w = page->decelerationWarning();
        return w.contains(QStringLiteral("on SPno3, SPno4")) &&
               w.contains(QString::fromUtf8("1700–3000 r/min in 0.5 s"));
    })) << qPrintable(page->decelerationWarning());
    // An edit to 2.5 s, not yet written, clears it: the warning is for the values as they will be.
    window->drives()->parameters(1)->setPending(QStringLiteral("spno3.decel"),
                                                QStringLiteral("2.5"));
    EXPECT_TRUE(waitFor([&] {
        return !page->decelerationWarning().contains(QStringLiteral("SPno3"));
    })) << qPrintable(page->decelerationWarning());
}

TEST_F(MainWindowRunTest, TheDcControllerPageFollowsTheControllerAndShowsStoppedAfterStopAll)
{
    select({7});
    TestRunPanel* panel = showTestRun(*window, 7);
    ASSERT_TRUE(panel);
    ASSERT_TRUE(waitFor([&] { return panel->commandsEnabled(); }));
    panel->findChild<QLineEdit*>(QStringLiteral("speed"))->setText(QStringLiteral("30"));
    clickAndConfirm(panel, QStringLiteral("setSpeed"));
    DcControllerPage* page = pageOf<DcControllerPage>(*window, 7);
    ASSERT_TRUE(page);
    ASSERT_TRUE(page->liveState());
    showPage(*window, page);
    // The settings page watches the controller itself (the Test run page is hidden now).
    RunLiveState* live = page->liveState();
    ASSERT_TRUE(waitFor([&] { return live->stateText().contains(QStringLiteral("30.0 %")); }))
        << qPrintable(live->stateText());
    EXPECT_TRUE(window->monitorHub()->isWatched(7));
    window->stopAllButton()->stopAll();
    ASSERT_TRUE(waitFor([&] { return live->stateText() == QStringLiteral("Stopped"); }, 15000))
        << qPrintable(live->stateText());
    if (QMessageBox* result = window->stopAllButton()->resultWindow())
        result->close();
}
