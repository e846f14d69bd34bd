#include "model/files/BackupFile.h"
#include "tests/ui/files/FileDialogsFixture.h"
#include "ui/files/BackupViewer.h"
#include "ui/files/FileActions.h"

#include <QFileInfo>
#include <QMenu>
#include <QTreeWidget>

using namespace opentop;

namespace {

class BackupDialogTest : public test::FileDialogsFixture
{
};

class BackupViewerTest : public test::FileDialogsFixture
{
};

const QString kAccel = QStringLiteral("spno2.accel");

} // namespace

TEST_F(BackupDialogTest, BacksUpADriveAndTheFileHoldsItsValue)
{
    start(QStringLiteral("dbu200@1"), {1});
    setRegister(1, address(QStringLiteral("dbu"), kAccel), 123);
    const QString file = path(QStringLiteral("one.json"));
    ASSERT_TRUE(backUp({1}, file));

    QString error;
    const auto loaded = BackupFile::load(file, ProfileRegistry::builtIn(), &error);
    ASSERT_TRUE(loaded) << qPrintable(error);
    ASSERT_EQ(loaded->slaves(), QVector<int>{1});
    const BackupParameter* accel = loaded->device(1)->parameter(kAccel);
    ASSERT_TRUE(accel);
    EXPECT_EQ(accel->registers, QVector<quint16>{123});
    EXPECT_EQ(loaded->connection.kind, QStringLiteral("sim"));
}

TEST_F(BackupDialogTest, CancelOfAWholeBusBackupNamesTheDrivesNotReadAndSavesNothing)
{
    start(QStringLiteral("dbu200@1,dbu400@2,dcpid@5"), {1, 2, 5});
    const QString file = path(QStringLiteral("bus.json"));
    BackupDialog dialog(drives.get(), settings);
    ASSERT_TRUE(runUntil(&dialog, &BackupDialog::backupFinished, [&] {
        dialog.startBackup({1, 2, 5}, file);
        EXPECT_TRUE(dialog.isRunning());
        dialog.cancel(); // while drive 1 is being read
    }));
    EXPECT_EQ(dialog.readSlaves(), QVector<int>{1});
    EXPECT_EQ(dialog.notRead(), (QVector<int>{2, 5}));
    EXPECT_FALSE(dialog.isSaved());
    EXPECT_FALSE(QFileInfo::exists(file));
    EXPECT_TRUE(dialog.message().contains(QStringLiteral("2, 5"))) << qPrintable(dialog.message());
    EXPECT_EQ(dialog.cellText(2, BackupDialog::Result), QStringLiteral("Not read (cancelled)"));

    // The user decides to keep what was read.
    ASSERT_TRUE(dialog.saveReadDrives());
    QString error;
    const auto loaded = BackupFile::load(file, ProfileRegistry::builtIn(), &error);
    ASSERT_TRUE(loaded) << qPrintable(error);
    EXPECT_EQ(loaded->slaves(), QVector<int>{1});
}

TEST_F(BackupDialogTest, BacksUpTheWholeBusInOneFile)
{
    start(QStringLiteral("dbu200@1,dcpid@5"), {1, 5});
    const QString file = path(QStringLiteral("bus.json"));
    ASSERT_TRUE(backUp({1, 5}, file));
    QString error;
    const auto loaded = BackupFile::load(file, ProfileRegistry::builtIn(), &error);
    ASSERT_TRUE(loaded) << qPrintable(error);
    EXPECT_EQ(loaded->slaves(), (QVector<int>{1, 5}));
}

TEST_F(BackupViewerTest, ShowsEachDrivesSettingsWithUnitsAndRegisters)
{
    start(QStringLiteral("dbu200@1"), {1});
    setRegister(1, address(QStringLiteral("dbu"), kAccel), 25);
    const QString file = path(QStringLiteral("view.json"));
    ASSERT_TRUE(backUp({1}, file));
    BackupViewer viewer;
    ASSERT_TRUE(viewer.open(file)) << qPrintable(viewer.errorText());
    EXPECT_TRUE(viewer.errorText().isEmpty());
    EXPECT_EQ(viewer.cellText(1, kAccel, BackupViewer::Value), QStringLiteral("2.5 s"));
    EXPECT_EQ(viewer.cellText(1, kAccel, BackupViewer::Registers), QStringLiteral("25 (0x0019)"));
    EXPECT_FALSE(viewer.cellText(1, kAccel, BackupViewer::Label).isEmpty());
    EXPECT_TRUE(viewer.headerText().contains(QStringLiteral("OpenTOP")));
}

TEST_F(BackupViewerTest, RefusesAChangedFileAndANonJsonFileWithTheReason)
{
    start(QStringLiteral("dbu200@1"), {1});
    const QString file = path(QStringLiteral("good.json"));
    ASSERT_TRUE(backUp({1}, file));
    QByteArray data = readFile(file);
    const int at = int(data.indexOf("\"created\": \"")) + 12;
    ASSERT_GT(at, 12);
    data[at] = data[at] == '1' ? '2' : '1'; // another year: the checksum no longer matches
    const QString changed = path(QStringLiteral("changed.json"));
    writeFile(changed, data);
    const QString garbage = path(QStringLiteral("garbage.json"));
    writeFile(garbage, "this is not a backup\n");
    const int writes = writesSent();

    BackupViewer viewer;
    EXPECT_FALSE(viewer.open(changed));
    EXPECT_TRUE(viewer.errorText().contains(QStringLiteral("changed")))
        << qPrintable(viewer.errorText());
    EXPECT_EQ(viewer.tree()->topLevelItemCount(), 0);
    EXPECT_FALSE(viewer.open(garbage));
    EXPECT_TRUE(viewer.errorText().contains(QStringLiteral("JSON")))
        << qPrintable(viewer.errorText());
    EXPECT_EQ(writesSent(), writes);
}

TEST_F(BackupDialogTest, FileActionsAreDisabledWhenTheyCannotWork)
{
    start(QStringLiteral("dbu200@1,dcpid@5"), {1, 5});
    QWidget window;
    QMenu menu;
    BusDrives* current = nullptr;
    QVector<int> selected;
    FileActions actions(
        &window, &menu, [&current] { return current; }, [&selected] { return selected; },
        [this] { return settings; });
    EXPECT_EQ(menu.actions().size(), 6); // five actions and a separator
    EXPECT_FALSE(actions.backupSelectedAction()->isEnabled());
    EXPECT_FALSE(actions.backupBusAction()->isEnabled());
    EXPECT_FALSE(actions.restoreAction()->isEnabled());
    EXPECT_TRUE(actions.openAction()->isEnabled()); // a file needs no bus
    EXPECT_TRUE(actions.compareAction()->isEnabled());

    current = drives.get();
    actions.updateActions();
    EXPECT_FALSE(actions.backupSelectedAction()->isEnabled()); // nothing selected
    EXPECT_TRUE(actions.backupBusAction()->isEnabled());
    EXPECT_TRUE(actions.restoreAction()->isEnabled());
    EXPECT_EQ(actions.identifiedDrives(), (QVector<int>{1, 5}));
    selected = {5};
    actions.updateActions();
    EXPECT_TRUE(actions.backupSelectedAction()->isEnabled());
}
