// Issue 24, item 3, through the real MainWindow on a serial line: opentop-sim on a pty with
// wire timing and a half-duplex line. Drive 1's monitor page is open (it polls) when F5 scans
// the bus: the scan owns the bus (polling waits, the page says so and its values are not shown
// as live), every drive is found, the DC controller included, and polling goes on afterwards.
// An address that answers but cannot be identified is named in the scan's result.
#include "model/bus/BusScanner.h"
#include "tests/ui/main/MainWindowFixture.h"

#include "tests/e2e/SimProcess.h"
#include "ui/widgets/StaleLook.h"

#include <QAction>
#include <QKeySequence>

namespace opentop::test {

namespace {

class MainWindowScanTest : public MainWindowFixture
{
protected:
    // Connects the window to `sim`'s pty at `baud` with drive 1 named, as the connection dialog
    // does with a remembered bus.
    void connectToSim(const SimProcess& sim, int baud, int timeoutMs = 200)
    {
        ConnectionSettings serial;
        serial.port = sim.pty;
        serial.baud = baud;
        serial.timeoutMs = timeoutMs;
        window->connectTo(serial, {{1, QStringLiteral("dbu200")}});
        ASSERT_TRUE(waitFor([&] {
            return window->isConnected() && window->client() &&
                   window->client()->settings().port == sim.pty && window->drives() &&
                   window->drives()->info(1).state == DeviceInfo::State::Present;
        }));
    }

    // Drive 1's monitor page in front and live.
    MonitorPage* monitorDrive1()
    {
        select({1});
        MonitorPage* page = nullptr;
        EXPECT_TRUE(waitFor([&] {
            page = window->workspace()->drive()
                       ? qobject_cast<MonitorPage*>(window->workspace()->tabs()->currentWidget())
                       : nullptr;
            return page && page->staleLook()->state() == Freshness::State::Live;
        }));
        return page;
    }

    QAction* scanAction() const
    {
        for (QAction* a : window->findChildren<QAction*>())
            if (a->text() == QStringLiteral("&Scan bus"))
                return a;
        return nullptr;
    }

    static bool startSim(SimProcess& sim, const QString& devices, int baud)
    {
        QString error;
        const bool ok = sim.start({QStringLiteral("--devices"), devices,
                                   QStringLiteral("--wire-timing"), QStringLiteral("--half-duplex"),
                                   QStringLiteral("--baud"), QString::number(baud)},
                                  &error);
        EXPECT_TRUE(ok) << qPrintable(error);
        return ok;
    }
};

} // namespace

TEST_F(MainWindowScanTest, F5WhileDrive1IsMonitoredFindsEveryDriveAndPollingWaitsForTheScan)
{
    // Drive 60 answers after the scan's 18 ms wait (30 ms turnaround): found by its late reply.
    // (A 14 ms one, on the wait's edge, was missed once in 20 runs on a fully loaded machine
    // with no trace on the master's side; followed up in issue 28's late-reply work.)
    SimProcess sim;
    ASSERT_TRUE(startSim(
        sim, QStringLiteral("dbu200@1,dbu400@150,dcpid@7,dbu200@60{turnaround=30}"), 19200));
    connectToSim(sim, 19200);
    MonitorPage* page = monitorDrive1();
    ASSERT_NE(page, nullptr);
    const int samplesBefore = page->samplesShown();
    ASSERT_GT(samplesBefore, 0);

    QAction* scan = scanAction();
    ASSERT_NE(scan, nullptr);
    EXPECT_EQ(scan->shortcut(), QKeySequence(Qt::Key_F5));
    scan->trigger();
    ASSERT_TRUE(window->busPanel()->isScanning());
    EXPECT_TRUE(window->client()->isPollingHeld());
    // What the engineer sees while the scan runs: polling waits, and says so; the values are
    // the last ones read and are not shown as live; the bus list's lights are grey.
    bool sawWaiting = false;
    bool sawNotLive = false;
    bool lightGrey = false;
    int samplesDuring = -1;
    ASSERT_TRUE(waitFor(
        [&] {
            if (window->busPanel()->isScanning()) {
                sawWaiting |= page->pollText().startsWith(
                    QStringLiteral("Polling waits for the bus scan: last answer "));
                sawNotLive |= page->staleLook()->state() == Freshness::State::Stale;
                lightGrey |= window->statusPoller()->shownLed(1, QDateTime::currentDateTimeUtc()) ==
                             DriveStatus::Led::Grey;
                if (samplesDuring < 0)
                    samplesDuring = page->samplesShown();
            }
            return !window->busPanel()->isScanning();
        },
        30000));
    EXPECT_TRUE(sawWaiting) << qPrintable(page->pollText());
    EXPECT_TRUE(sawNotLive);
    EXPECT_TRUE(lightGrey);
    EXPECT_FALSE(window->busPanel()->message().contains(QStringLiteral("Polling waits")));
    // At most the poll already on the wire when the scan began came in during the scan.
    EXPECT_LE(page->samplesShown(), samplesDuring + 1);

    // Every drive, the DC controller and the slow drive included.
    BusDrives* drives = window->drives();
    for (int slave : {1, 7, 60, 150})
        EXPECT_EQ(drives->info(slave).state, DeviceInfo::State::Present)
            << slave << ": " << qPrintable(drives->info(slave).detail);
    EXPECT_EQ(drives->info(7).family, QStringLiteral("dcpid"));
    EXPECT_TRUE(window->busPanel()->message().startsWith(
        QStringLiteral("4 drives found on machine numbers 1–247 in ")))
        << qPrintable(window->busPanel()->message());
    // Polling goes on, and the values are live again.
    EXPECT_FALSE(window->client()->isPollingHeld());
    EXPECT_TRUE(waitFor([&] {
        return page->samplesShown() > samplesDuring + 2 &&
               page->staleLook()->state() == Freshness::State::Live;
    }));
    EXPECT_FALSE(page->pollText().contains(QStringLiteral("Polling waits")))
        << qPrintable(page->pollText());
}

TEST_F(MainWindowScanTest, TheIssuesScanOf1To10At9600FindsTheDcController)
{
    SimProcess sim;
    ASSERT_TRUE(startSim(sim, QStringLiteral("dbu200@1,dbu400@150,dcpid@7"), 9600));
    connectToSim(sim, 9600);
    ASSERT_NE(monitorDrive1(), nullptr);
    window->busPanel()->startScan(1, 10);
    ASSERT_TRUE(waitFor([&] { return !window->busPanel()->isScanning(); }, 30000));
    EXPECT_EQ(window->drives()->info(7).state, DeviceInfo::State::Present)
        << qPrintable(window->drives()->info(7).detail);
    EXPECT_EQ(window->drives()->info(7).family, QStringLiteral("dcpid"));
    EXPECT_TRUE(window->busPanel()->message().startsWith(
        QStringLiteral("2 drives found on machine numbers 1–10 in ")))
        << qPrintable(window->busPanel()->message());
}

TEST_F(MainWindowScanTest, AnAddressThatAnsweredButCouldNotBeIdentifiedIsNamedInTheResult)
{
    // The DC controller at 7 answers 100 ms after the gap: with a 50 ms timeout even its second
    // chances (76 ms) end before its identification reply. Its late answer shows it is there.
    SimProcess sim;
    ASSERT_TRUE(startSim(sim, QStringLiteral("dbu200@1,dcpid@7{turnaround=100}"), 19200));
    connectToSim(sim, 19200, 50);
    BusPanel* panel = window->busPanel();
    panel->startScan(1, 10);
    // What the panel says at the retry, caught when the scanner announces it (a busy machine
    // may pass that moment between two looks).
    bool sawRetry = false;
    auto* scanner = panel->findChild<BusScanner*>();
    ASSERT_NE(scanner, nullptr);
    // (Connected after the panel's own slot, so it runs after the panel has said it.)
    QObject::connect(scanner, &BusScanner::identificationRetry, panel, [&](int slave, int attempt) {
        if (slave == 7 && attempt == 1)
            sawRetry |= panel->message().startsWith(QStringLiteral(
                "Machine number 7 answered, identification failed: retrying (1 of 3)…"));
    });
    ASSERT_TRUE(waitFor([&] { return !panel->isScanning(); }, 30000));
    EXPECT_TRUE(sawRetry);
    const QString result = panel->message();
    EXPECT_TRUE(result.startsWith(QStringLiteral("1 drive found on machine numbers 1–10 in ")))
        << qPrintable(result);
    EXPECT_TRUE(result.contains(QStringLiteral(
        "Machine number 7 answered, but its identification failed, also when asked again: add "
        "it by hand with Add drive…, or check its line settings and scan again.")))
        << qPrintable(result);
    // The list has it, as what it is.
    const BusListModel* list = panel->model();
    const int row = list->rowOf(7);
    ASSERT_GE(row, 0);
    EXPECT_EQ(list->index(row, BusListModel::State).data().toString(),
              QStringLiteral("answered, identification failed"));
    EXPECT_TRUE(list->index(row, BusListModel::State)
                    .data(Qt::ToolTipRole)
                    .toString()
                    .contains(QStringLiteral("add it by hand")));
}

} // namespace opentop::test
