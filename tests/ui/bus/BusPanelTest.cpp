#include "ui/bus/BusPanel.h"
#include "connection/BackendFactory.h"
#include "model/bus/BusDrives.h"
#include "model/bus/DriveStatusPoller.h"
#include "model/profile/ProfileRegistry.h"
#include "model/session/DeviceSession.h"
#include "sim/SimBus.h"
#include "transport/ModbusClient.h"
#include "ui/bus/BusListModel.h"

#include <QAction>
#include <QBrush>
#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QIcon>
#include <QItemSelectionModel>
#include <QMenu>
#include <QProgressBar>
#include <QSignalSpy>
#include <QTableView>
#include <functional>
#include <gtest/gtest.h>
#include <memory>

using namespace opentop;
using Led = DriveStatus::Led;

namespace {

bool waitFor(const std::function<bool()>& condition, int ms = 10000)
{
    QDeadlineTimer deadline(ms);
    while (!condition() && !deadline.hasExpired())
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
    return condition();
}

class BusPanelTest : public ::testing::Test
{
protected:
    void open(const QString& spec)
    {
        ConnectionSettings settings;
        settings.kind = ConnectionSettings::Kind::Simulated;
        settings.simSpec = spec;
        settings.timeoutMs = 100;
        made = BackendFactory::makeClient(settings);
        ASSERT_TRUE(made.client) << qPrintable(made.error);
        bool opened = false;
        QObject::connect(made.client.get(), &ModbusClient::opened,
                         [&](bool ok, const QString&) { opened = ok; });
        made.client->open();
        ASSERT_TRUE(waitFor([&] { return opened; }));
        drives = std::make_unique<BusDrives>(made.client.get(), ProfileRegistry::builtIn());
        poller = std::make_unique<DriveStatusPoller>(drives.get());
        poller->setInterval(30);
        panel = std::make_unique<BusPanel>(drives.get(), poller.get());
        panel->show();
    }

    void TearDown() override
    {
        panel.reset();
        poller.reset();
        drives.reset();
        made.client.reset();
    }

    void scan(int from, int to)
    {
        panel->startScan(from, to);
        ASSERT_TRUE(waitFor([&] { return !panel->isScanning(); }, 30000));
    }

    BusListModel* model() const { return panel->model(); }
    QString text(int slave, int column) const
    {
        return model()->index(model()->rowOf(slave), column).data().toString();
    }
    QVariant data(int slave, int column, int role) const
    {
        return model()->index(model()->rowOf(slave), column).data(role);
    }
    Led led(int slave) const { return Led(data(slave, 0, BusListModel::LedRole).toInt()); }

    DeviceSession::Outcome write(int slave, const char* name, const QString& value)
    {
        DeviceSession::WriteOptions explicitly;
        explicitly.explicitCommand = true;
        DeviceSession::Outcome result;
        bool done = false;
        drives->session(slave)->write(QLatin1String(name), value, explicitly,
                                      [&](const DeviceSession::Outcome& o) {
                                          result = o;
                                          done = true;
                                      });
        EXPECT_TRUE(waitFor([&] { return done; }));
        return result;
    }

    BackendFactory::Made made;
    std::unique_ptr<BusDrives> drives;
    std::unique_ptr<DriveStatusPoller> poller;
    std::unique_ptr<BusPanel> panel;
};

} // namespace

TEST_F(BusPanelTest, ScanFindsTheDrivesAndFillsTheProgressBar)
{
    open(QStringLiteral("dbu200@1,dbu400@150,dcpid@7"));
    QVector<int> rowsSeen; // rows appear while the scan runs, not only at its end
    QObject::connect(model(), &QAbstractItemModel::rowsInserted, [&] {
        if (panel->isScanning())
            rowsSeen << model()->rowCount();
    });
    panel->startScan(1, 160);
    EXPECT_TRUE(panel->isScanning());
    EXPECT_TRUE(panel->progressBar()->isVisible());
    ASSERT_TRUE(waitFor([&] { return !panel->isScanning(); }, 30000));
    EXPECT_EQ(rowsSeen, (QVector<int>{1, 2, 3}));
    EXPECT_EQ(panel->progressBar()->value(), 160);
    EXPECT_EQ(panel->progressBar()->maximum(), 160);
    EXPECT_EQ(drives->slaves(), (QVector<int>{1, 7, 150}));
    ASSERT_EQ(model()->rowCount(), 3);
    EXPECT_EQ(text(150, BusListModel::MachineNumber), QStringLiteral("150"));
    EXPECT_EQ(text(150, BusListModel::Switches), QStringLiteral("SW1=9 SW2=6"));
    EXPECT_EQ(text(7, BusListModel::Family), QStringLiteral("DCPID"));
    EXPECT_EQ(text(1, BusListModel::Model), QStringLiteral("DBU — variant unknown"));
    EXPECT_TRUE(text(1, BusListModel::Firmware).startsWith(QStringLiteral("V")));
    EXPECT_TRUE(panel->message().contains(QStringLiteral("3 drive(s) found")))
        << qPrintable(panel->message());
}

TEST_F(BusPanelTest, CancelStopsEarlyAndSaysHowFar)
{
    open(QStringLiteral("dbu200@1,dbu400@150"));
    panel->startScan(1, 247);
    ASSERT_TRUE(waitFor([&] { return panel->progressBar()->value() >= 5; }));
    panel->cancelScan();
    ASSERT_TRUE(waitFor([&] { return !panel->isScanning(); }));
    EXPECT_LT(panel->progressBar()->value(), 247);
    EXPECT_EQ(drives->slaves(), QVector<int>{1});
    EXPECT_TRUE(panel->message().contains(QStringLiteral("cancelled")))
        << qPrintable(panel->message());
    EXPECT_TRUE(panel->message().contains(QStringLiteral("of 247")));
}

TEST_F(BusPanelTest, AddDriveByNumberIdentifiesOnlyThatNumber)
{
    open(QStringLiteral("dbu200@1,dbu400@150,dcpid@7"));
    int added = 0;
    QObject::connect(panel.get(), &BusPanel::driveAddedByNumber, [&](int) { ++added; });
    panel->addDrive(7);
    ASSERT_TRUE(waitFor([&] { return added == 1; }));
    EXPECT_EQ(drives->slaves(), QVector<int>{7});
    EXPECT_EQ(drives->info(7).state, DeviceInfo::State::Present);
    EXPECT_EQ(text(7, BusListModel::Family), QStringLiteral("DCPID"));
    panel->addDrive(42);
    ASSERT_TRUE(waitFor([&] { return added == 2; }));
    EXPECT_EQ(text(42, BusListModel::State), DeviceInfo::stateText(DeviceInfo::State::Absent));
}

TEST_F(BusPanelTest, AGarbledAddressIsFlaggedWithWhatToCheck)
{
    open(QStringLiteral("dbu200@3"));
    FaultRates rates;
    rates.crc = 1.0;
    made.simBus->setFaults(FaultInjector(rates));
    scan(1, 4);
    ASSERT_EQ(drives->slaves(), QVector<int>{3});
    EXPECT_EQ(drives->info(3).state, DeviceInfo::State::Garbled);
    EXPECT_TRUE(data(3, BusListModel::State, BusListModel::ProblemRole).toBool());
    EXPECT_EQ(data(3, BusListModel::MachineNumber, Qt::ForegroundRole).value<QBrush>().color(),
              QColor(0xb0, 0x1c, 0x1c));
    const QString tip = data(3, BusListModel::State, Qt::ToolTipRole).toString();
    // What to check, with the switch positions of this number for each family.
    EXPECT_TRUE(tip.contains(QStringLiteral("SW1=0 SW2=3"))) << qPrintable(tip);
    EXPECT_TRUE(tip.contains(QStringLiteral("DIP ON: 1,2"))) << qPrintable(tip);
    EXPECT_TRUE(tip.contains(QStringLiteral("machine number 3"))) << qPrintable(tip);
}

TEST_F(BusPanelTest, StatusLightsFollowAStartedDrive)
{
    open(QStringLiteral("dbu200@1"));
    scan(1, 2);
    poller->start();
    ASSERT_TRUE(waitFor([&] { return led(1) == Led::Green; }));
    EXPECT_EQ(text(1, BusListModel::State), QStringLiteral("online"));
    EXPECT_EQ(text(1, BusListModel::Priority), QStringLiteral("I/O priority"));
    ASSERT_TRUE(write(1, "core.control_priority", QStringLiteral("2")).ok);
    ASSERT_TRUE(write(1, "run.select", QStringLiteral("SPno2")).ok);
    ASSERT_TRUE(write(1, "run.start", QStringLiteral("START")).ok);
    ASSERT_TRUE(waitFor([&] { return led(1) == Led::Orange; }));
    EXPECT_EQ(text(1, BusListModel::Priority), QStringLiteral("Communication priority"));
    EXPECT_TRUE(data(1, BusListModel::Light, Qt::ToolTipRole)
                    .toString()
                    .contains(QStringLiteral("Running CW")));
    EXPECT_FALSE(data(1, BusListModel::Light, Qt::DecorationRole).value<QIcon>().isNull());

    ASSERT_TRUE(made.simBus->control(1, {QStringLiteral("alarm"), QStringLiteral("7")}).ok);
    ASSERT_TRUE(waitFor([&] { return led(1) == Led::Red; }));
    const QString tip = data(1, BusListModel::Light, Qt::ToolTipRole).toString();
    EXPECT_TRUE(tip.contains(QStringLiteral("Alarm AL007 Overload"))) << qPrintable(tip);
    // The colour's name and the manual's meaning from the profile's status LED table.
    EXPECT_TRUE(tip.contains(QStringLiteral("Status light Red: "))) << qPrintable(tip);
    EXPECT_TRUE(tip.contains(QStringLiteral("The drive's manual: Alarm; Flashes")))
        << qPrintable(tip);
}

TEST_F(BusPanelTest, APollThatChangesNothingRepaintsNothing)
{
    open(QStringLiteral("dbu200@1"));
    scan(1, 2);
    poller->start();
    ASSERT_TRUE(waitFor([&] { return led(1) == Led::Green; }));
    // A dozen polls that find the drive as it was: the row is not reported changed, so the
    // list neither repaints it nor measures every row again for its column widths.
    QSignalSpy spy(model(), &QAbstractItemModel::dataChanged);
    waitFor([] { return false; }, 400);
    EXPECT_EQ(spy.count(), 0);
    ASSERT_TRUE(write(1, "core.control_priority", QStringLiteral("2")).ok);
    ASSERT_TRUE(waitFor([&] { return !spy.isEmpty(); }));
    EXPECT_EQ(text(1, BusListModel::Priority), QStringLiteral("Communication priority"));
}

TEST_F(BusPanelTest, AScanHoldsTheBusAndTheLightsAreNotLiveMeanwhile)
{
    // The scanner holds the bus (polling waits in the client, not by a trick of this panel),
    // the lights go grey at once and the message says why; afterwards polling goes on.
    open(QStringLiteral("dbu200@1"));
    scan(1, 1);
    poller->start();
    ASSERT_TRUE(waitFor([&] { return led(1) == Led::Green; }));
    panel->startScan(1, 3);
    EXPECT_TRUE(made.client->isPollingHeld());
    EXPECT_TRUE(poller->isActive());
    EXPECT_EQ(led(1), Led::Grey);
    EXPECT_TRUE(panel->message().contains(QStringLiteral("Polling waits until the scan is over")))
        << qPrintable(panel->message());
    ASSERT_TRUE(waitFor([&] { return !panel->isScanning(); }));
    EXPECT_FALSE(made.client->isPollingHeld());
    const int cycles = poller->cyclesCompleted();
    EXPECT_TRUE(waitFor([&] { return poller->cyclesCompleted() > cycles + 1; }));
    EXPECT_TRUE(waitFor([&] { return led(1) == Led::Green; }));
}

TEST_F(BusPanelTest, TheVariantCanBeChosenWhereTheDriveDoesNotReportIt)
{
    open(QStringLiteral("dbu400@150,dcpid@7"));
    int added = 0;
    QObject::connect(panel.get(), &BusPanel::driveAddedByNumber, [&](int) { ++added; });
    panel->addDrive(7);
    panel->addDrive(150);
    ASSERT_TRUE(waitFor([&] { return added == 2; }));
    ASSERT_EQ(drives->slaves(), (QVector<int>{7, 150}));
    EXPECT_TRUE(drives->info(150).variant.isEmpty());
    std::unique_ptr<QMenu> menu(panel->contextMenuFor({150}, nullptr));
    QAction* dbu400 = menu->findChild<QAction*>(QStringLiteral("dbu400"));
    ASSERT_TRUE(dbu400);
    EXPECT_EQ(dbu400->text(), QStringLiteral("DBU400-D4"));
    dbu400->trigger();
    EXPECT_EQ(drives->info(150).variant, QStringLiteral("dbu400"));
    EXPECT_EQ(drives->session(150)->variant(), QStringLiteral("dbu400"));
    EXPECT_EQ(text(150, BusListModel::Model), QStringLiteral("DBU400-D4"));
    // The DC controller has one model: no variant choice.
    std::unique_ptr<QMenu> dcMenu(panel->contextMenuFor({7}, nullptr));
    EXPECT_FALSE(dcMenu->findChild<QAction*>(QStringLiteral("dbu400")));
}

TEST_F(BusPanelTest, MultiSelectionReportsTheMachineNumbers)
{
    open(QStringLiteral("dbu200@1,dcpid@7"));
    scan(1, 8);
    QVector<int> reported;
    QObject::connect(panel.get(), &BusPanel::selectionChanged,
                     [&](const QVector<int>& slaves) { reported = slaves; });
    QItemSelectionModel* selection = panel->view()->selectionModel();
    // The first drive found is selected by itself; start from nothing.
    EXPECT_EQ(panel->selectedSlaves(), QVector<int>{1});
    selection->clearSelection();
    EXPECT_TRUE(reported.isEmpty());
    selection->select(model()->index(0, 0),
                      QItemSelectionModel::Select | QItemSelectionModel::Rows);
    EXPECT_EQ(reported, QVector<int>{1});
    selection->select(model()->index(1, 0),
                      QItemSelectionModel::Select | QItemSelectionModel::Rows);
    EXPECT_EQ(reported, (QVector<int>{1, 7}));
    EXPECT_EQ(panel->selectedSlaves(), (QVector<int>{1, 7}));
}
