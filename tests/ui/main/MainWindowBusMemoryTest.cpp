// The bus remembered per connection and offered back after a reconnection or a restart; the
// page header naming the model once the variant is set; a simulated bus marked as such.
#include "tests/ui/main/MainWindowFixture.h"
#include "ui/bus/BusRecallBar.h"

#include <QFile>
#include <QProcess>

using namespace opentop;
using namespace opentop::test;

namespace {

class MainWindowBusMemoryTest : public MainWindowFixture
{
protected:
    // Settings of their own: other test processes running at the same time remember the same
    // simulated bus in the shared test settings.
    void SetUp() override
    {
        m_appName = QCoreApplication::applicationName();
        QCoreApplication::setApplicationName(
            QStringLiteral("busmemory-%1").arg(QCoreApplication::applicationPid()));
        MainWindowFixture::SetUp();
    }
    void TearDown() override
    {
        window.reset();
        QSettings settings;
        settings.clear();
        settings.sync();
        QFile::remove(settings.fileName());
        QCoreApplication::setApplicationName(m_appName);
    }
    QString m_appName;

    ConnectionSettings simulated() const
    {
        ConnectionSettings settings;
        settings.kind = ConnectionSettings::Kind::Simulated;
        settings.simSpec = QStringLiteral("dbu200@1,dbu200@2,dbu400@150,dcpid@7");
        settings.timeoutMs = 100;
        return settings;
    }

    // Reconnects as the connection dialog does: no drives named.
    void reconnect() { connectAndWait(simulated()); }
    // The window keeps a working bus until the new one is open: wait for the new one.
    void connectAndWait(const ConnectionSettings& settings)
    {
        bool opened = false;
        QObject::connect(
            window.get(), &MainWindow::connectionChanged, window.get(),
            [&](bool up) { opened = up; }, Qt::SingleShotConnection);
        window->connectTo(settings);
        ASSERT_TRUE(waitFor([&] { return opened; }));
    }
};

} // namespace

TEST_F(MainWindowBusMemoryTest, TheDrivesLastSeenAreOfferedAfterReconnectingWithHandSetVariants)
{
    // Drives named by the caller: nothing to offer.
    ASSERT_NE(window->recallBar(), nullptr);
    EXPECT_FALSE(window->recallBar()->isVisible());
    // The engineer sets drive 2's variant by hand (the bus list's context menu does this).
    window->drives()->setVariant(2, QStringLiteral("dbu400"));

    reconnect();
    EXPECT_TRUE(window->drives()->slaves().isEmpty()); // nothing assumed
    BusRecallBar* bar = window->recallBar();
    ASSERT_TRUE(bar->isVisible());
    EXPECT_TRUE(bar->text().contains(QStringLiteral("1 (DBU200-D), 2 (DBU400-D4), 7 (")) &&
                bar->text().contains(QStringLiteral("150 (DBU400-D4)")))
        << qPrintable(bar->text());
    EXPECT_EQ(bar->restoreButton()->text(), QStringLiteral("&Restore the 4 drives last seen"));
    bar->restoreButton()->click();
    EXPECT_FALSE(bar->isVisible());
    ASSERT_TRUE(waitFor([&] {
        return window->drives()->slaves().size() == 4 &&
               window->drives()->info(150).state == DeviceInfo::State::Present;
    }));
    EXPECT_EQ(window->drives()->info(2).model, QStringLiteral("DBU400-D4"));
    EXPECT_EQ(window->drives()->info(1).model, QStringLiteral("DBU200-D"));

    // After a restart of the program (another window, same settings store) it is offered too.
    window.reset();
    window = std::make_unique<MainWindow>(
        [this](const ConnectionSettings& s, TrafficLog* log, QString* error) {
            auto made = BackendFactory::makeClient(s, log);
            bus = made.simBus;
            if (error)
                *error = made.error;
            return std::move(made.client);
        });
    window->show();
    reconnect();
    ASSERT_TRUE(window->recallBar()->isVisible());
    EXPECT_TRUE(window->recallBar()->text().contains(QStringLiteral("2 (DBU400-D4)")));
}

TEST_F(MainWindowBusMemoryTest, WithNothingRememberedAScanIsOffered)
{
    ConnectionSettings other = simulated();
    other.simSpec = QStringLiteral("dcpid@9");
    connectAndWait(other);
    BusRecallBar* bar = window->recallBar();
    ASSERT_TRUE(bar->isVisible());
    EXPECT_TRUE(bar->text().contains(QStringLiteral("Scan the bus")));
    EXPECT_FALSE(bar->restoreButton()->isVisible());
    EXPECT_TRUE(bar->scanButton()->isVisible());
    // A scan started elsewhere (the bus list, F5) finds the drive: the bar's "no drive is
    // known" would be false now, and it goes (seen on screen: it stayed after a toolbar scan).
    window->busPanel()->startScan(8, 10);
    EXPECT_TRUE(waitFor([&] { return !bar->isVisible(); }, 15000)) << qPrintable(bar->text());
    EXPECT_TRUE(window->drives()->slaves().contains(9));
}

TEST_F(MainWindowBusMemoryTest, ThePageHeaderNamesTheModelOnceTheVariantIsSet)
{
    connectAndWait(simulated()); // nothing named: the variant is not known
    window->busPanel()->addDrive(150);
    ASSERT_TRUE(
        waitFor([&] { return window->drives()->info(150).state == DeviceInfo::State::Present; }));
    select({150});
    ASSERT_TRUE(waitFor([&] { return window->workspace()->drive() != nullptr; }));
    const QString familyTitle = window->workspace()->titleText();
    EXPECT_FALSE(familyTitle.contains(QStringLiteral("DBU400-D4"))) << qPrintable(familyTitle);
    window->drives()->setVariant(150, QStringLiteral("dbu400"));
    EXPECT_TRUE(window->workspace()->titleText().contains(QStringLiteral("DBU400-D4")))
        << qPrintable(window->workspace()->titleText());
}

TEST_F(MainWindowBusMemoryTest, ASimulatedBusIsMarkedInTheWindowAndARealOneIsNot)
{
    QLabel* banner = window->simulatedBanner();
    ASSERT_NE(banner, nullptr);
    EXPECT_TRUE(banner->isVisible());
    EXPECT_TRUE(banner->text().startsWith(QStringLiteral("SIMULATED BUS")));
    EXPECT_GT(banner->height(), 0);
    EXPECT_TRUE(window->windowTitle().contains(QStringLiteral("SIMULATED")));
    EXPECT_TRUE(waitFor([&] {
        return window->connectionLabel()->toolTip().contains(QStringLiteral("simulated"));
    }));
    // A gateway where nothing listens: the simulated bus stays, and so does its marker.
    ConnectionSettings tcp;
    tcp.kind = ConnectionSettings::Kind::Tcp;
    tcp.host = QStringLiteral("127.0.0.1");
    tcp.tcpPort = 1;
    tcp.timeoutMs = 100;
    QTimer dismiss; // the "Cannot connect" message
    QObject::connect(&dismiss, &QTimer::timeout, [] {
        if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget()))
            box->accept();
    });
    dismiss.start(20);
    window->connectTo(tcp);
    QTest::qWait(300);
    EXPECT_TRUE(window->isConnected());
    EXPECT_TRUE(banner->isVisible());
    EXPECT_TRUE(window->windowTitle().contains(QStringLiteral("SIMULATED")));
    // Before any connection (and on hardware) there is no marker.
    MainWindow fresh([](const ConnectionSettings&, TrafficLog*, QString*) {
        return std::unique_ptr<ModbusClient>();
    });
    fresh.show();
    EXPECT_FALSE(fresh.simulatedBanner()->isVisible());
    EXPECT_FALSE(fresh.windowTitle().contains(QStringLiteral("SIMULATED")));
}

// One memory for both programs: a scan on the command line is what the window offers next.
TEST_F(MainWindowBusMemoryTest, AScanOnTheCommandLineIsOfferedByTheWindow)
{
    // The names the real window runs under (app/gui/main.cpp): its settings file is then the
    // one the command line uses.
    struct Organization
    {
        QString before = QCoreApplication::organizationName();
        ~Organization() { QCoreApplication::setOrganizationName(before); }
    } organization;
    QCoreApplication::setOrganizationName(QStringLiteral("OpenTOP"));
    QCoreApplication::setApplicationName(QStringLiteral("OpenTOP"));
    const QString spec = QStringLiteral("dbu200@4,dcpid@6");
    QProcess cli;
    cli.start(QStringLiteral(OPENTOP_BIN_DIR "/opentop-cli"),
              {QStringLiteral("--sim"), spec, QStringLiteral("scan"), QStringLiteral("--to"),
               QStringLiteral("8")});
    ASSERT_TRUE(cli.waitForFinished(30000));
    ASSERT_EQ(cli.exitCode(), 0) << cli.readAllStandardError().toStdString();
    ConnectionSettings settings = simulated();
    settings.simSpec = spec;
    connectAndWait(settings);
    BusRecallBar* bar = window->recallBar();
    ASSERT_TRUE(bar->isVisible());
    EXPECT_TRUE(bar->text().contains(QStringLiteral("4 (")) &&
                bar->text().contains(QStringLiteral("6 (")))
        << qPrintable(bar->text());
    EXPECT_EQ(bar->restoreButton()->text(), QStringLiteral("&Restore the 2 drives last seen"));
}
