// The monitor page against the in-process simulated bus: a started drive ramps up, the
// terminals light, the drive's panel is mirrored, an alarm is shown with its remedy.
#include "ui/monitor/MonitorPage.h"
#include "model/bus/BusDrives.h"
#include "model/monitor/MonitorHub.h"
#include "model/session/DeviceParameters.h"
#include "tests/model/DriveSimFixture.h"
#include "ui/monitor/PanelMirrorView.h"
#include "ui/monitor/TerminalLamps.h"
#include "ui/trends/TrendChart.h"
#include "ui/widgets/StatusLight.h"

#include <QSettings>

using namespace opentop;
using namespace opentop::test;

namespace {

class MonitorPageTest : public DriveSimFixture
{
protected:
    void open(const QString& spec, int slave)
    {
        startBus(spec);
        drives = identifiedDrives({slave});
        hub = std::make_unique<MonitorHub>(drives.get());
        hub->setInterval(50);
        bool read = false;
        drives->parameters(slave)->refresh({}, [&read](int) { read = true; });
        ASSERT_TRUE(waitUntil([&] { return read; }));
        page = std::make_unique<MonitorPage>(hub.get(), drives->parameters(slave));
        page->resize(1000, 700);
        page->show();
    }

    void TearDown() override
    {
        page.reset();
        hub.reset();
        drives.reset();
        DriveSimFixture::TearDown();
    }

    std::unique_ptr<BusDrives> drives;
    std::unique_ptr<MonitorHub> hub;
    std::unique_ptr<MonitorPage> page;
};

} // namespace

TEST_F(MonitorPageTest, AStartedDriveRampsUpAndItsTerminalsLight)
{
    open(QStringLiteral("dbu200@1"), 1);
    ASSERT_TRUE(waitUntil([&] { return page->samplesShown() >= 2; }));
    EXPECT_EQ(page->currentSpeedText(), QStringLiteral("0 r/min"));
    EXPECT_EQ(page->statusText(), QStringLiteral("Stopped"));
    ASSERT_NE(page->lamps(QStringLiteral("status.inputs")), nullptr);
    EXPECT_EQ(page->lamps(QStringLiteral("status.inputs"))->stateText(),
              QStringLiteral("X0 OFF, X1 OFF, X2 OFF, X3 OFF"));
    // X0 (CW/STOP in Mode2) on: the motor runs up to the Ext-VR speed.
    control(1, {QStringLiteral("vr"), QStringLiteral("2400")});
    control(1, {QStringLiteral("input"), QStringLiteral("1")});
    QVector<int> speeds;
    ASSERT_TRUE(waitUntil(
        [&] {
            const int v = page->currentSpeedText().section(QLatin1Char(' '), 0, 0).toInt();
            if (speeds.isEmpty() || speeds.last() != v)
                speeds << v;
            return v == 2400;
        },
        8000))
        << qPrintable(page->currentSpeedText());
    // A ramp: several values on the way, never going down.
    EXPECT_GE(speeds.size(), 4);
    EXPECT_TRUE(std::is_sorted(speeds.cbegin(), speeds.cend()));
    EXPECT_EQ(page->statusText(), QStringLiteral("Running CW"));
    EXPECT_EQ(page->valueText(QStringLiteral("status.target_speed")), QStringLiteral("2400 r/min"));
    EXPECT_EQ(page->valueText(QStringLiteral("status.driver.spno_bits")), QStringLiteral("SPno1"));
    EXPECT_EQ(page->lamps(QStringLiteral("status.inputs"))->stateText(),
              QStringLiteral("X0 ON, X1 OFF, X2 OFF, X3 OFF"));
    // Each terminal says what it is for (Mode2 defaults: X0 is CW/STOP).
    EXPECT_EQ(page->lamps(QStringLiteral("status.inputs"))->functionText(QStringLiteral("io.x0")),
              drives->parameters(1)->deviceText(QStringLiteral("io.x0")));
    EXPECT_FALSE(page->lamps(QStringLiteral("status.outputs"))
                     ->functionText(QStringLiteral("io.y0"))
                     .isEmpty());
    // The panel shows the speed in its unit (r/min with 3 decimals, fitted to 5 digits).
    EXPECT_EQ(page->panel()->panelText(), QStringLiteral("2400.0"));
    EXPECT_EQ(page->panel()->light()->led(), DriveStatus::Led::Orange);
}

TEST_F(MonitorPageTest, PanelFollowsTheDrivesDisplaySettingAndReverseRuns)
{
    open(QStringLiteral("dbu200@4"), 4);
    // The panel set to show the load rate while running.
    control(4, {QStringLiteral("set"), QStringLiteral("0x1001"), QStringLiteral("4")});
    bool read = false;
    drives->parameters(4)->refresh({QStringLiteral("core.panel_display")},
                                   [&read](int) { read = true; });
    ASSERT_TRUE(waitUntil([&] { return read; }));
    control(4, {QStringLiteral("input"), QStringLiteral("2")}); // X1: CCW/STOP
    ASSERT_TRUE(waitUntil([&] { return page->statusText() == QStringLiteral("Running CCW"); }));
    EXPECT_TRUE(page->panel()->panelText().startsWith(QStringLiteral("LD")))
        << qPrintable(page->panel()->panelText());
    EXPECT_EQ(page->panel()->light()->led(), DriveStatus::Led::SkyBlue);
    EXPECT_TRUE(page->currentSpeedText().startsWith(QLatin1Char('-')))
        << qPrintable(page->currentSpeedText());
}

TEST_F(MonitorPageTest, AnAlarmIsShownWithItsRemedyAndOnThePanel)
{
    open(QStringLiteral("dbu200@1"), 1);
    control(1, {QStringLiteral("alarm"), QStringLiteral("7")});
    ASSERT_TRUE(waitUntil([&] { return page->alarmText().contains(QStringLiteral("AL007")); }));
    EXPECT_TRUE(page->alarmText().contains(QStringLiteral("Overload")));
    EXPECT_EQ(page->panel()->panelText(), QStringLiteral("AL007"));
    EXPECT_EQ(page->panel()->light()->led(), DriveStatus::Led::Red);
}

TEST_F(MonitorPageTest, DcControllerSpeedNeedsTheMotorsCommutationsPerRevolution)
{
    QSettings().remove(QStringLiteral("monitor"));
    open(QStringLiteral("dcpid@7"), 7);
    EXPECT_EQ(page->panel(), nullptr); // the controller has no panel to mirror
    // No target or load: the chart shows the frequency with the PWM duty and the current.
    EXPECT_EQ(page->chart()->sources(),
              (QVector<TrendSource>{{7, QStringLiteral("status.commutation")},
                                    {7, QStringLiteral("status.pwm")},
                                    {7, QStringLiteral("status.current")}}));
    ASSERT_TRUE(waitUntil([&] { return page->samplesShown() >= 1; }));
    EXPECT_TRUE(page->currentSpeedText().contains(QStringLiteral("set the commutations")))
        << qPrintable(page->currentSpeedText());
    EXPECT_EQ(page->valueText(QStringLiteral("status.current")), QStringLiteral("0.00 A"));
    EXPECT_EQ(page->valueText(QStringLiteral("status.sq1_level")), QStringLiteral("Low"));
    page->setCommutationsPerRevolution(6);
    EXPECT_TRUE(page->currentSpeedText().endsWith(QStringLiteral("0 r/min")))
        << qPrintable(page->currentSpeedText());
    EXPECT_EQ(QSettings().value(QStringLiteral("monitor/commutationsPerRevolution/7")).toInt(), 6);
}

TEST_F(MonitorPageTest, AnOutputLampSaysWhatItsTerminalIsAssignedTo)
{
    open(QStringLiteral("dbu200@1"), 1);
    ASSERT_TRUE(waitUntil([&] { return page->samplesShown() >= 1; }));
    TerminalLamps* outputs = page->lamps(QStringLiteral("status.outputs"));
    ASSERT_NE(outputs, nullptr);
    EXPECT_EQ(outputs->functionParameters(),
              (QStringList{QStringLiteral("io.y0"), QStringLiteral("io.y1")}));
    // Y1 set to another function on the drive: once read, its lamp says so.
    DeviceParameters* parameters = drives->parameters(1);
    const QString before = outputs->functionText(QStringLiteral("io.y1"));
    EXPECT_EQ(before, QStringLiteral("Alarm-Out")); // the factory default
    control(1, {QStringLiteral("set"), QStringLiteral("0x210B"), QStringLiteral("5")});
    bool read = false;
    parameters->refresh({QStringLiteral("io.y1")}, [&read](int) { read = true; });
    ASSERT_TRUE(waitUntil([&] { return read; }));
    EXPECT_EQ(outputs->functionText(QStringLiteral("io.y1")), QStringLiteral("Warning-Out"));
}
