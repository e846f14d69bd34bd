// A scan that finds nothing offers the DC controller's fixed potentiometer-mode settings
// (9600 8E1, address 1): the bus panel's button reconnects with them and scans that address.
#include "tests/ui/main/MainWindowFixture.h"

#include "transport/ModbusClient.h"
#include "ui/bus/BusPanel.h"

#include <QPushButton>
#include <QSignalSpy>

using namespace opentop;
using namespace opentop::test;

namespace {

class MainWindowFixedLineTest : public MainWindowFixture
{
};

} // namespace

TEST_F(MainWindowFixedLineTest, AnEmptyScanOffersARescanAtTheFixedSettingsThatFindsTheController)
{
    ConnectionSettings settings;
    settings.kind = ConnectionSettings::Kind::Simulated;
    settings.simSpec = QStringLiteral("dcpid@1");
    settings.timeoutMs = 100;
    settings.baud = 19200;
    settings.parity = 'N';
    QSignalSpy changed(window.get(), &MainWindow::connectionChanged);
    window->connectTo(settings);
    auto upCount = [&changed] {
        int n = 0;
        for (const QList<QVariant>& args : changed)
            n += args.at(0).toBool() ? 1 : 0;
        return n;
    };
    ASSERT_TRUE(waitFor([&] { return upCount() == 1; }));
    BusPanel* panel = window->busPanel();
    EXPECT_FALSE(panel->fixedLineButton()->isVisible());
    panel->startScan(2, 3);
    ASSERT_TRUE(waitFor([&] { return !panel->isScanning(); }, 15000));
    ASSERT_TRUE(panel->fixedLineButton()->isVisible()) << qPrintable(panel->message());
    EXPECT_TRUE(panel->message().contains(QStringLiteral(
        "A DC controller in potentiometer/analog control mode talks only at 9600 bit/s, 8E1, "
        "address 1.")))
        << qPrintable(panel->message());
    EXPECT_EQ(panel->fixedLineButton()->text(), QStringLiteral("Rescan at 9600 8E1, address 1"));

    panel->fixedLineButton()->click();
    ASSERT_TRUE(waitFor([&] { return upCount() == 2; }));
    EXPECT_EQ(window->client()->settings().baud, 9600);
    EXPECT_EQ(window->client()->settings().parity, 'E');
    EXPECT_EQ(window->client()->settings().stopBits, 1);
    ASSERT_TRUE(waitFor(
        [&] {
            return window->drives()->info(1).state == DeviceInfo::State::Present &&
                   !window->busPanel()->isScanning();
        },
        15000))
        << qPrintable(window->busPanel()->message());
    EXPECT_EQ(window->drives()->info(1).family, QStringLiteral("dcpid"));
    EXPECT_FALSE(window->busPanel()->fixedLineButton()->isVisible());
}
