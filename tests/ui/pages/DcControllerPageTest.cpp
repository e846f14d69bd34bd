#include "ui/pages/DcControllerPage.h"
#include "model/session/DeviceParameters.h"
#include "sim/SimDevice.h"
#include "tests/ui/UiSimFixture.h"
#include "ui/workspace/ParameterField.h"

#include <QLabel>

using namespace opentop;

namespace {

class DcControllerPageTest : public test::UiSimFixture
{
protected:
    void SetUp() override
    {
        startBus(QStringLiteral("dcpid@7"));
        params = std::make_unique<DeviceParameters>(session(7));
        page = std::make_unique<DcControllerPage>(params.get());
        page->setConfirm([this](const QString&, const QString& text) {
            asked << text;
            return answer;
        });
        ASSERT_TRUE(
            runUntil(page.get(), &ParameterPage::operationFinished, [this] { page->refresh(); }));
    }
    void TearDown() override
    {
        page.reset();
        params.reset();
        DriveSimFixture::TearDown();
    }

    void writeSetting(const QString& name, const QString& text)
    {
        page->field(name)->enter(text);
        ASSERT_TRUE(page->field(name)->problem().isEmpty())
            << qPrintable(page->field(name)->problem());
        ASSERT_TRUE(
            runUntil(page.get(), &ParameterPage::operationFinished, [this] { page->writePage(); }));
        ASSERT_TRUE(params->pendingNames().isEmpty());
    }
    bool store(const QString& command)
    {
        return runUntil(page.get(), &DcControllerPage::storeFinished,
                        [&] { page->store(command); });
    }

    std::unique_ptr<DeviceParameters> params;
    std::unique_ptr<DcControllerPage> page;
    QStringList asked;
    bool answer = true;
};

} // namespace

TEST_F(DcControllerPageTest, StoredViaTheBannerSurvivesPowerCycleUnstoredDoesNot)
{
    EXPECT_FALSE(page->bannerShown());
    const int commLossBefore = simRegister(7, 0x008E);
    writeSetting(QStringLiteral("config.stall_time"), QStringLiteral("2.5"));
    EXPECT_TRUE(page->bannerShown());
    EXPECT_EQ(page->unstored(), QStringList{QStringLiteral("store.config")});

    ASSERT_TRUE(store(QStringLiteral("store.config")));
    ASSERT_EQ(asked.size(), 1);
    EXPECT_TRUE(asked.first().contains(QStringLiteral("Stall stop time"))) << qPrintable(asked[0]);
    EXPECT_FALSE(page->bannerShown());

    const int commLoss = commLossBefore == 15 ? 20 : 15;
    writeSetting(QStringLiteral("config.comm_loss_time"), QString::number(commLoss / 10.0));
    EXPECT_TRUE(page->bannerShown());
    EXPECT_EQ(simRegister(7, 0x008E), commLoss); // in effect now

    control(7, {QStringLiteral("power-cycle")});
    EXPECT_EQ(simRegister(7, 0x0081), 25);             // stored
    EXPECT_EQ(simRegister(7, 0x008E), commLossBefore); // lost
}

TEST_F(DcControllerPageTest, PidAndPresetHaveTheirOwnStoreCommands)
{
    writeSetting(QStringLiteral("pid.d_period"), QStringLiteral("20"));
    writeSetting(QStringLiteral("preset.trigger"), QStringLiteral("1"));
    EXPECT_EQ(page->unstored(),
              (QStringList{QStringLiteral("store.pid"), QStringLiteral("store.preset")}));
    ASSERT_TRUE(store(QStringLiteral("store.pid")));
    EXPECT_TRUE(page->bannerShown()); // the preset is still owed
    control(7, {QStringLiteral("power-cycle")});
    EXPECT_EQ(simRegister(7, 0x0097), 20);
    EXPECT_NE(simRegister(7, 0x00A1), 1);
}

TEST_F(DcControllerPageTest, DeclinedStoreSendsNothing)
{
    writeSetting(QStringLiteral("config.brake_current"), QStringLiteral("1.5"));
    const int before = writesSent();
    answer = false;
    page->store(QStringLiteral("store.config"));
    QCoreApplication::processEvents();
    EXPECT_EQ(writesSent(), before);
    EXPECT_TRUE(page->bannerShown());
}

TEST_F(DcControllerPageTest, ReloadDiscardsUnstoredConfiguration)
{
    const int stored = simRegister(7, 0x0081);
    writeSetting(QStringLiteral("config.stall_time"), QString::number((stored + 7) / 10.0));
    EXPECT_EQ(simRegister(7, 0x0081), stored + 7);
    ASSERT_TRUE(runUntil(page.get(), &DcControllerPage::storeFinished,
                         [this] { page->reloadStoredConfiguration(); }));
    ASSERT_EQ(asked.size(), 1);
    EXPECT_TRUE(asked.first().contains(QStringLiteral("discarded")));
    EXPECT_EQ(simRegister(7, 0x0081), stored);
    EXPECT_FALSE(page->bannerShown());
    // The page shows the reloaded value.
    EXPECT_EQ(params->entry(QStringLiteral("config.stall_time"))->device.raw, stored);
}

TEST_F(DcControllerPageTest, PresetSpeedsFollowThePendingPresetMode)
{
    // 150 is no PWM duty (at most 100.0 %) but a valid speed loop frequency (1–1000 1/s).
    page->field(QStringLiteral("preset.speed_mode"))->enter(QStringLiteral("0"));
    page->field(QStringLiteral("preset.forward_speed"))->enter(QStringLiteral("150"));
    EXPECT_FALSE(page->field(QStringLiteral("preset.forward_speed"))->problem().isEmpty());
    page->field(QStringLiteral("preset.speed_mode"))->enter(QStringLiteral("2"));
    page->field(QStringLiteral("preset.forward_speed"))->enter(QStringLiteral("150"));
    EXPECT_TRUE(page->field(QStringLiteral("preset.forward_speed"))->problem().isEmpty())
        << qPrintable(page->field(QStringLiteral("preset.forward_speed"))->problem());
}

TEST_F(DcControllerPageTest, SettingTheSerialLockAsksFirstAndSaysHowToUndoIt)
{
    const QString lock = QStringLiteral("config.serial_lock");
    answer = false;
    page->field(lock)->enter(QStringLiteral("Disabled"));
    ASSERT_TRUE(page->field(lock)->problem().isEmpty());
    page->writePage();
    ASSERT_EQ(asked.size(), 1);
    EXPECT_TRUE(asked.first().contains(QStringLiteral("prohibits configuration over the serial")))
        << qPrintable(asked.first());
    EXPECT_TRUE(asked.first().contains(QStringLiteral("9600 bit/s, 8E1, address 1")))
        << qPrintable(asked.first());
    EXPECT_EQ(simRegister(7, 0x008D), 0); // declined: nothing sent
    EXPECT_EQ(params->pendingNames(), QStringList{lock});

    answer = true;
    ASSERT_TRUE(
        runUntil(page.get(), &ParameterPage::operationFinished, [this] { page->writePage(); }));
    EXPECT_EQ(asked.size(), 2);
    EXPECT_EQ(simRegister(7, 0x008D), 1);
    // Lifting it asks nothing.
    writeSetting(lock, QStringLiteral("Allowed"));
    EXPECT_EQ(asked.size(), 2);
    EXPECT_EQ(simRegister(7, 0x008D), 0);
}

TEST_F(DcControllerPageTest, BaudRateIsStoredByItsBlockWriteAndUsedAfterThePowerCycle)
{
    writeSetting(QStringLiteral("config.stall_time"), QStringLiteral("1.5"));
    EXPECT_EQ(page->unstored(), QStringList{QStringLiteral("store.config")});
    writeSetting(QStringLiteral("config.baud"), QStringLiteral("38400"));
    // The 15-register write stored the whole configuration: nothing left to store.
    EXPECT_FALSE(page->bannerShown());
    EXPECT_EQ(bus->device(7)->lineBaud(), 9600);
    control(7, {QStringLiteral("power-cycle")});
    EXPECT_EQ(bus->device(7)->lineBaud(), 38400);
    EXPECT_EQ(simRegister(7, 0x008B), 38400);
    EXPECT_EQ(simRegister(7, 0x0081), 15);
}

TEST_F(DcControllerPageTest, PidAboveTheRecommendationShowsAWarningAtTheField)
{
    ParameterField* p = page->field(QStringLiteral("pid.p"));
    p->enter(QStringLiteral("2.5"));
    EXPECT_TRUE(p->problem().isEmpty()) << qPrintable(p->problem());
    EXPECT_TRUE(p->warning().contains(QStringLiteral("recommended range 0.0000–1.0000")))
        << qPrintable(p->warning());
    EXPECT_EQ(p->messageLabel()->text(), p->warning());
    ASSERT_TRUE(
        runUntil(page.get(), &ParameterPage::operationFinished, [this] { page->writePage(); }));
    EXPECT_TRUE(params->pendingNames().isEmpty());
    // Written; the drive's value is still outside the recommendation, and the field says so.
    EXPECT_FALSE(p->warning().isEmpty());
    writeSetting(QStringLiteral("pid.p"), QStringLiteral("0.4"));
    EXPECT_TRUE(p->warning().isEmpty()) << qPrintable(p->warning());
    EXPECT_TRUE(p->messageLabel()->isHidden());
}
