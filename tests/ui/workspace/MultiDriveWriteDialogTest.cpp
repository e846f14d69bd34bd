#include "ui/workspace/MultiDriveWriteDialog.h"
#include "model/bus/BusDrives.h"
#include "tests/ui/UiSimFixture.h"

#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QMessageBox>
#include <QPushButton>

using namespace opentop;

namespace {

class MultiDriveWriteDialogTest : public test::UiSimFixture
{
protected:
    void start(const QString& spec, const QVector<QPair<int, QString>>& drives,
               const QString& family = QStringLiteral("dbu"))
    {
        startBus(spec);
        busDrives = std::make_unique<BusDrives>(client.get(), ProfileRegistry::builtIn());
        for (const auto& d : drives) {
            DeviceInfo info;
            info.slave = d.first;
            info.state = DeviceInfo::State::Present;
            info.family = family;
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

TEST_F(MultiDriveWriteDialogTest, SaysWhatIsOutsideTheRecommendedRangeAndAsksBeforeASerialLock)
{
    start(QStringLiteral("dcpid@7,dcpid@8"), {{7, QString()}, {8, QString()}},
          QStringLiteral("dcpid"));
    MultiDriveWriteDialog dialog(busDrives.get(), {7, 8}, QStringLiteral("pid.p"));
    ASSERT_TRUE(waitUntil([&] { return !dialog.busy(); }));
    // Allowed 0-100, recommended 0-1: written with a warning, as a page or the command line say.
    dialog.setValueText(QStringLiteral("5"));
    EXPECT_TRUE(dialog.problem().isEmpty()) << qPrintable(dialog.problem());
    EXPECT_TRUE(dialog.messageText().contains(QStringLiteral("Drive 7:")) &&
                dialog.messageText().contains(QStringLiteral("Drive 8:")) &&
                dialog.messageText().contains(QStringLiteral("recommended")))
        << qPrintable(dialog.messageText());
    dialog.setValueText(QStringLiteral("0.5"));
    EXPECT_FALSE(dialog.messageText().contains(QStringLiteral("Warning")))
        << qPrintable(dialog.messageText());

    // The serial lock can shut the program out of both drives: said, then asked.
    dialog.setParameter(QStringLiteral("config.serial_lock"));
    ASSERT_TRUE(waitUntil([&] { return !dialog.busy(); }));
    dialog.setValueText(QStringLiteral("Disabled"));
    EXPECT_TRUE(dialog.messageText().contains(QStringLiteral("prohibits configuration")))
        << qPrintable(dialog.messageText());
    const int writes = framesSent(6) + framesSent(16);
    dialog.writeToAll();
    auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
    ASSERT_TRUE(box);
    EXPECT_TRUE(box->text().contains(QStringLiteral("Drive 7:")) &&
                box->text().contains(QStringLiteral("Drive 8:")) &&
                box->text().contains(QStringLiteral("9600")))
        << qPrintable(box->text());
    EXPECT_EQ(static_cast<QAbstractButton*>(box->defaultButton()),
              box->button(QMessageBox::Cancel));
    box->button(QMessageBox::Cancel)->click();
    QCoreApplication::processEvents();
    EXPECT_FALSE(dialog.busy());
    EXPECT_EQ(framesSent(6) + framesSent(16), writes) << "nothing sent after Cancel";

    bool finished = false;
    QObject::connect(&dialog, &MultiDriveWriteDialog::writeFinished, [&] { finished = true; });
    dialog.writeToAll();
    box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
    ASSERT_TRUE(box);
    box->button(QMessageBox::Yes)->click();
    ASSERT_TRUE(waitUntil([&] { return finished; }));
    const quint16 lock = ProfileRegistry::builtIn()
                             .family(QStringLiteral("dcpid"))
                             ->parameter(QStringLiteral("config.serial_lock"))
                             ->address;
    EXPECT_EQ(simRegister(7, lock), 1);
    EXPECT_EQ(simRegister(8, lock), 1);
}
