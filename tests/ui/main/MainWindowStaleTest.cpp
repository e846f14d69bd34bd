// Nothing stale looks live, through the real MainWindow: the Alarms page follows the drive and
// the banner, a lost link greys every live view, the monitor's sample rate is the real one and
// the Hold lamp says when holding does not apply (issue 10, items 8, 9 and 12).
#include "tests/ui/main/MainWindowFixture.h"

#include "ui/alarms/AlarmBanner.h"
#include "ui/alarms/AlarmsPage.h"
#include "ui/monitor/PanelMirrorView.h"
#include "ui/monitor/TerminalLamps.h"
#include "ui/widgets/StaleLook.h"
#include "ui/widgets/StatusLight.h"

#include <QAbstractButton>
#include <QDateTime>

namespace opentop::test {

using MainWindowStaleTest = MainWindowFixture;

namespace {

MonitorPage* monitorPageOf(MainWindow* window)
{
    QTabWidget* tabs = window->workspace()->tabs();
    for (int i = 0; i < tabs->count(); ++i) {
        if (auto* page = qobject_cast<MonitorPage*>(tabs->widget(i)))
            return page;
    }
    return nullptr;
}

double rateShown(const MonitorPage* page)
{
    const QRegularExpressionMatch m =
        QRegularExpression(QStringLiteral("([0-9.]+) samples/s")).match(page->pollText());
    return m.hasMatch() ? m.captured(1).toDouble() : -1.0;
}

} // namespace

TEST_F(MainWindowStaleTest, AnAlarmRaisedInTheSimulatorAppearsOnTheOpenAlarmsPageWithoutAClick)
{
    select({1});
    ASSERT_TRUE(waitFor([&] { return window->alarmsPage() != nullptr; }));
    AlarmsPage* page = window->alarmsPage();
    ASSERT_EQ(page->session()->slave(), 1);
    window->workspace()->tabs()->setCurrentWidget(page);
    ASSERT_TRUE(waitFor([&] { return !page->isBusy() && page->shownAlarmActive().has_value(); }));
    EXPECT_FALSE(*page->shownAlarmActive());
    EXPECT_TRUE(page->statusText().contains(QStringLiteral("No alarm is active")))
        << qPrintable(page->statusText());

    // Nobody clicks Re-read: the page reads again because the drive reports the alarm.
    ASSERT_TRUE(bus->control(1, {QStringLiteral("alarm"), QStringLiteral("0x0B")}).ok);
    ASSERT_TRUE(waitFor([&] {
        return !page->isBusy() && page->shownAlarmActive().value_or(false) &&
               page->shownAlarmCode() == 0x0B;
    })) << qPrintable(page->statusText());
    EXPECT_TRUE(page->statusText().contains(QStringLiteral("Alarm active")))
        << qPrintable(page->statusText());
    EXPECT_GT(page->autoRefreshes(), 0);
    // The banner says the same as the page.
    auto* banner = window->findChild<AlarmBanner*>();
    ASSERT_NE(banner, nullptr);
    ASSERT_TRUE(waitFor([&] { return banner->hasAlarm(); }));
    EXPECT_EQ(banner->currentSlave(), 1);
    // The page's alarm state is live, with its age.
    EXPECT_TRUE(page->ageText().contains(QStringLiteral("updated"))) << qPrintable(page->ageText());

    // A power cycle clears it: the page no longer says "Alarm active", nor does the banner.
    ASSERT_TRUE(bus->control(1, {QStringLiteral("power-cycle")}).ok);
    ASSERT_TRUE(waitFor([&] {
        return !page->isBusy() && page->shownAlarmActive() == std::optional<bool>(false);
    })) << qPrintable(page->statusText());
    EXPECT_FALSE(page->statusText().contains(QStringLiteral("Alarm active")))
        << qPrintable(page->statusText());
    EXPECT_TRUE(page->statusText().contains(QStringLiteral("No alarm is active")));
    EXPECT_TRUE(waitFor([&] { return !banner->hasAlarm(); }));
}

TEST_F(MainWindowStaleTest, TheBannersShowOpensThatDrivesAlarmsPage)
{
    select({2});
    ASSERT_TRUE(waitFor([&] { return window->alarmsPage() != nullptr; }));
    ASSERT_NE(qobject_cast<MonitorPage*>(window->workspace()->tabs()->currentWidget()), nullptr);
    ASSERT_TRUE(bus->control(150, {QStringLiteral("alarm"), QStringLiteral("0x0B")}).ok);
    auto* banner = window->findChild<AlarmBanner*>();
    ASSERT_NE(banner, nullptr);
    ASSERT_TRUE(waitFor([&] { return banner->hasAlarm() && banner->currentSlave() == 150; }));
    QAbstractButton* show = nullptr;
    for (QAbstractButton* b : banner->findChildren<QAbstractButton*>()) {
        if (b->text() == QLatin1String("Show"))
            show = b;
    }
    ASSERT_NE(show, nullptr);
    show->click();
    EXPECT_EQ(window->busPanel()->selectedSlaves(), QVector<int>{150});
    AlarmsPage* page = window->alarmsPage();
    ASSERT_NE(page, nullptr);
    EXPECT_EQ(page->session()->slave(), 150);
    EXPECT_EQ(window->workspace()->tabs()->currentWidget(), page);
    ASSERT_TRUE(waitFor([&] { return !page->isBusy() && page->shownAlarmActive().has_value(); }));
    EXPECT_TRUE(*page->shownAlarmActive()) << qPrintable(page->statusText());
    EXPECT_TRUE(page->statusText().contains(QStringLiteral("Alarm active")));
}

TEST_F(MainWindowStaleTest, ALostLinkGreysEveryLiveViewAtOnceAndNothingStaysGreen)
{
    select({1});
    window->monitorAll();
    ASSERT_TRUE(waitFor([&] { return monitorPageOf(window.get()) != nullptr; }));
    MonitorPage* page = monitorPageOf(window.get());
    BusListModel* list = window->busPanel()->model();
    BusOverviewModel* overview = window->busOverview()->model();
    const auto listLed = [&](int slave) {
        return DriveStatus::Led(list->index(list->rowOf(slave), BusListModel::Light)
                                    .data(BusListModel::LedRole)
                                    .toInt());
    };
    const auto overviewStale = [&](int slave) {
        return overview->index(overview->rowOf(slave), BusOverviewModel::Speed)
            .data(BusOverviewModel::StaleRole)
            .toBool();
    };
    // Live first: values with their age, green lights.
    ASSERT_TRUE(waitFor([&] {
        return page->staleLook()->state() == Freshness::State::Live &&
               listLed(1) == DriveStatus::Led::Green && !overviewStale(1) && !overviewStale(150);
    }));
    EXPECT_TRUE(page->pollText().contains(QStringLiteral("updated")))
        << qPrintable(page->pollText());
    int liveValues = 0;
    for (QLabel* label : page->findChildren<QLabel*>()) {
        EXPECT_FALSE(StaleLook::isStale(label)) << qPrintable(label->text());
        liveValues += label->property(StaleLook::kProperty).isValid() ? 1 : 0;
    }
    EXPECT_GE(liveValues, 3); // the values follow the look
    EXPECT_EQ(window->linkLight()->led(), DriveStatus::Led::Green);
    ASSERT_NE(page->panel(), nullptr);
    EXPECT_FALSE(page->panel()->isStale());
    EXPECT_EQ(page->panel()->light()->led(), DriveStatus::Led::Green);
    TerminalLamps* lamps = page->lamps(QStringLiteral("status.inputs"));
    if (!lamps) {
        for (TerminalLamps* l : page->findChildren<TerminalLamps*>())
            lamps = l;
    }
    ASSERT_NE(lamps, nullptr);
    EXPECT_FALSE(lamps->isStale());

    // The adapter is pulled out.
    const qint64 lostAt = QDateTime::currentMSecsSinceEpoch();
    bus->setUnplugged(true);
    ASSERT_TRUE(waitFor([&] { return !window->isConnected(); }, 3000));
    ASSERT_TRUE(waitFor(
        [&] {
            return page->staleLook()->state() == Freshness::State::Stale && overviewStale(1) &&
                   overviewStale(150) && listLed(1) == DriveStatus::Led::Grey;
        },
        3000));
    // At once: well within the time a value would take to age (3 poll periods, 1.5 s at least).
    EXPECT_LT(QDateTime::currentMSecsSinceEpoch() - lostAt, 1500);

    // The Monitor page: every value grey, the time of the last answer given.
    EXPECT_TRUE(page->pollText().contains(QStringLiteral("last answer")))
        << qPrintable(page->pollText());
    int greyValues = 0;
    for (QLabel* label : page->findChildren<QLabel*>()) {
        if (StaleLook::isStale(label)) {
            ++greyValues;
            if (label->styleSheet().isEmpty()) { // a style sheet's colours are its own
                EXPECT_EQ(label->palette().color(QPalette::WindowText), StaleLook::grey())
                    << qPrintable(label->text());
            }
        }
    }
    EXPECT_GE(greyValues, 3);
    EXPECT_TRUE(lamps->isStale());
    EXPECT_TRUE(page->panel()->isStale());
    // Nothing green: not the mirrored LED, not the bus list's lights, not the status bar's.
    EXPECT_EQ(page->panel()->light()->led(), DriveStatus::Led::Grey);
    EXPECT_NE(window->linkLight()->led(), DriveStatus::Led::Green);
    for (int slave : window->drives()->slaves()) {
        EXPECT_EQ(listLed(slave), DriveStatus::Led::Grey) << slave;
        EXPECT_TRUE(list->index(list->rowOf(slave), BusListModel::Light)
                        .data(BusListModel::StaleRole)
                        .toBool())
            << slave;
    }
    // The overview: every drive's values grey, its last answer told.
    for (int slave : overview->slaves()) {
        EXPECT_TRUE(overviewStale(slave)) << slave;
        const QModelIndex speed = overview->index(overview->rowOf(slave), BusOverviewModel::Speed);
        EXPECT_EQ(speed.data(Qt::ForegroundRole).value<QBrush>().color(), StaleLook::grey());
        EXPECT_TRUE(overview->text(slave, BusOverviewModel::Communication)
                        .contains(QStringLiteral("connection lost")))
            << qPrintable(overview->text(slave, BusOverviewModel::Communication));
    }
    // Still so a few seconds later (nothing turns green again by itself).
    waitFor([] { return false; }, 1200);
    for (int slave : window->drives()->slaves())
        EXPECT_NE(listLed(slave), DriveStatus::Led::Green) << slave;
    EXPECT_EQ(page->staleLook()->state(), Freshness::State::Stale);
    if (auto* box = window->findChild<QMessageBox*>(QStringLiteral("connectionLostBox")))
        box->close();
}

TEST_F(MainWindowStaleTest, ADriveThatStopsAnsweringGreysOnItsOwn)
{
    select({1});
    ASSERT_TRUE(waitFor([&] { return monitorPageOf(window.get()) != nullptr; }));
    MonitorPage* page = monitorPageOf(window.get());
    ASSERT_TRUE(waitFor([&] { return page->staleLook()->state() == Freshness::State::Live; }));
    // Every reply lost, the link itself still open.
    FaultRates rates;
    rates.drop = 1.0;
    bus->setFaults(FaultInjector(rates));
    ASSERT_TRUE(
        waitFor([&] { return page->staleLook()->state() == Freshness::State::Stale; }, 5000));
    EXPECT_TRUE(window->isConnected());
    EXPECT_TRUE(page->pollText().contains(QStringLiteral("last answer")))
        << qPrintable(page->pollText());
    BusListModel* list = window->busPanel()->model();
    EXPECT_TRUE(waitFor(
        [&] {
            return DriveStatus::Led(list->index(list->rowOf(1), BusListModel::Light)
                                        .data(BusListModel::LedRole)
                                        .toInt()) != DriveStatus::Led::Green;
        },
        8000));
    // Answers again: live again.
    bus->setFaults(FaultInjector());
    EXPECT_TRUE(waitFor([&] { return page->staleLook()->state() == Freshness::State::Live; }, 5000))
        << qPrintable(page->pollText());
}

TEST_F(MainWindowStaleTest, TheSampleRateShownIsThePollRateAlsoAfterThePageWasHidden)
{
    select({1});
    ASSERT_TRUE(waitFor([&] { return monitorPageOf(window.get()) != nullptr; }));
    MonitorPage* page = monitorPageOf(window.get());
    window->monitorHub()->setInterval(200); // 5 Hz
    waitFor([] { return false; }, 2500);
    EXPECT_NEAR(rateShown(page), 5.0, 1.0) << qPrintable(page->pollText());
    // Another tab for a while: the drive is not polled meanwhile, and that is no slower rate.
    window->workspace()->tabs()->setCurrentIndex(1); // a settings page: it watches nothing
    ASSERT_TRUE(waitFor([&] { return !window->monitorHub()->isWatched(1); }, 3000));
    waitFor([] { return false; }, 2500);
    window->workspace()->tabs()->setCurrentWidget(page);
    waitFor([] { return false; }, 2000);
    EXPECT_NEAR(rateShown(page), 5.0, 1.0) << qPrintable(page->pollText());
    EXPECT_NEAR(window->monitorHub()->statistics(1).rate(), 5.0, 1.0);
}

TEST_F(MainWindowStaleTest, TheHoldLampIsNotApplicableWhileNoHoldingForceIsSet)
{
    // "No holding force" (0x100B = 0), while the drive's status bit says holding.
    bus->control(1, {QStringLiteral("set"), QStringLiteral("0x100B"), QStringLiteral("0")});
    select({1});
    ASSERT_TRUE(waitFor([&] { return monitorPageOf(window.get()) != nullptr; }));
    MonitorPage* page = monitorPageOf(window.get());
    ASSERT_TRUE(waitFor([&] { return page->lamps(QStringLiteral("status.driver")) != nullptr; }));
    TerminalLamps* lamps = page->lamps(QStringLiteral("status.driver"));
    ASSERT_TRUE(waitFor([&] { return lamps->stateText().contains(QStringLiteral("Hold n/a")); }))
        << qPrintable(lamps->stateText());
    // Holding force set: the lamp shows the drive's bit again.
    bus->control(1, {QStringLiteral("set"), QStringLiteral("0x100B"), QStringLiteral("1")});
    window->drives()->parameters(1)->refresh({QStringLiteral("core.stop_hold")});
    EXPECT_TRUE(waitFor([&] { return lamps->stateText().contains(QStringLiteral("Hold ON")); }))
        << qPrintable(lamps->stateText());
}

} // namespace opentop::test
