#include "workspace/MultiDriveWriteDialog.h"
#include "UiSimFixture.h"
#include "bus/BusDrives.h"

#include <QComboBox>

using namespace opentop;

namespace {

class MultiDriveWriteDialogTest : public test::UiSimFixture
{
protected:
    void start(const QString& spec, const QVector<QPair<int, QString>>& drives)
    {
        startBus(spec);
        busDrives = std::make_unique<BusDrives>(client.get(), ProfileRegistry::builtIn());
        for (const auto& d : drives) {
            DeviceInfo info;
            info.slave = d.first;
            info.state = DeviceInfo::State::Present;
            info.family = QStringLiteral("dbu");
            info.variant = d.second;
            info.model = d.second.toUpper();
            busDrives->update(info);
        }
    }
    void TearDown() override
    {
        busDrives.reset();
        DriveSimFixture::TearDown();
    }
    quint16 address(const QString& name) const
    {
        return ProfileRegistry::builtIn().family(QStringLiteral("dbu"))->parameter(name)->address;
    }

    std::unique_ptr<BusDrives> busDrives;
};

} // namespace

TEST_F(MultiDriveWriteDialogTest, WritesOneSettingToThreeDrivesAndEachHoldsIt)
{
    start(QStringLiteral("dbu200@1,dbu200@2,dbu200@3"), {{1, QStringLiteral("dbu200")},
                                                         {2, QStringLiteral("dbu200")},
                                                         {3, QStringLiteral("dbu200")}});
    const QString name = QStringLiteral("spno2.speed");
    MultiDriveWriteDialog dialog(busDrives.get(), {1, 2, 3}, name);
    EXPECT_EQ(dialog.parameterName(), name);
    // Only settings can be chosen: no commands, nothing read-only.
    auto* chooser = dialog.findChild<QComboBox*>();
    ASSERT_TRUE(chooser);
    EXPECT_LT(chooser->findData(QStringLiteral("run.start")), 0);
    ASSERT_TRUE(waitUntil([&] { return !dialog.busy(); }));
    for (int slave : {1, 2, 3}) {
        EXPECT_TRUE(dialog.cellText(slave, MultiDriveWriteDialog::CurrentValue)
                        .endsWith(QStringLiteral("r/min")))
            << qPrintable(dialog.cellText(slave, MultiDriveWriteDialog::CurrentValue));
    }

    dialog.setValueText(QStringLiteral("1234"));
    EXPECT_TRUE(dialog.problem().isEmpty()) << qPrintable(dialog.problem());
    ASSERT_TRUE(
        runUntil(&dialog, &MultiDriveWriteDialog::writeFinished, [&] { dialog.writeToAll(); }));
    for (int slave : {1, 2, 3}) {
        EXPECT_EQ(dialog.cellText(slave, MultiDriveWriteDialog::Result),
                  QStringLiteral("Written and verified"));
        EXPECT_EQ(dialog.cellText(slave, MultiDriveWriteDialog::CurrentValue),
                  QStringLiteral("1234 r/min"));
        EXPECT_EQ(simRegister(slave, address(name)), 1234);
    }
}

TEST_F(MultiDriveWriteDialogTest, RefusesAValueOneDriveDoesNotAllowAndSendsNothing)
{
    start(QStringLiteral("dbu200@1,dbu400@2"),
          {{1, QStringLiteral("dbu200")}, {2, QStringLiteral("dbu400")}});
    const QString name = QStringLiteral("spno2.speed");
    MultiDriveWriteDialog dialog(busDrives.get(), {1, 2}, name);
    ASSERT_TRUE(waitUntil([&] { return !dialog.busy(); }));
    const int before1 = simRegister(1, address(name));
    const int before2 = simRegister(2, address(name));
    const int writesBefore = writesSent();

    dialog.setValueText(QStringLiteral("280"));
    EXPECT_TRUE(dialog.problem().contains(QStringLiteral("drive 2")))
        << qPrintable(dialog.problem());
    EXPECT_TRUE(dialog.problem().contains(QStringLiteral("300–3000 r/min")))
        << qPrintable(dialog.problem());
    dialog.writeToAll();
    QCoreApplication::processEvents();
    EXPECT_FALSE(dialog.busy());
    EXPECT_EQ(writesSent(), writesBefore);
    EXPECT_EQ(simRegister(1, address(name)), before1);
    EXPECT_EQ(simRegister(2, address(name)), before2);
    EXPECT_TRUE(dialog.cellText(1, MultiDriveWriteDialog::Result).isEmpty());

    dialog.setValueText(QStringLiteral("300"));
    EXPECT_TRUE(dialog.problem().isEmpty()) << qPrintable(dialog.problem());
}

TEST_F(MultiDriveWriteDialogTest, WarnsOfAShortDecelerationFromHighSpeedButAllowsIt)
{
    start(QStringLiteral("dbu200@1,dbu200@2"),
          {{1, QStringLiteral("dbu200")}, {2, QStringLiteral("dbu200")}});
    // Drive 2's SPno2 decelerates in 0.5 s, drive 1's in 3 s.
    control(1, {QStringLiteral("set"), QString::number(address(QStringLiteral("spno2.decel"))),
                QStringLiteral("30")});
    control(2, {QStringLiteral("set"), QString::number(address(QStringLiteral("spno2.decel"))),
                QStringLiteral("5")});
    MultiDriveWriteDialog dialog(busDrives.get(), {1, 2}, QStringLiteral("spno2.speed"));
    ASSERT_TRUE(waitUntil([&] { return !dialog.busy(); }));
    dialog.setValueText(QStringLiteral("2500"));
    EXPECT_TRUE(dialog.problem().isEmpty()) << qPrintable(dialog.problem());
    EXPECT_TRUE(dialog.messageText().contains(QStringLiteral("Drive 2: SPno2 slows down")))
        << qPrintable(dialog.messageText());
    EXPECT_FALSE(dialog.messageText().contains(QStringLiteral("Drive 1:")));
    dialog.setValueText(QStringLiteral("1000"));
    EXPECT_FALSE(dialog.messageText().contains(QStringLiteral("Warning")));
}
