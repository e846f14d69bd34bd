#include "ui/files/CompareDialog.h"
#include "model/files/Comparer.h"
#include "tests/ui/files/FileDialogsFixture.h"
#include "ui/files/RestoreDialog.h"

#include <QTableWidget>

using namespace opentop;

namespace {

const QString kDbu = QStringLiteral("dbu");
const QString kAccel = QStringLiteral("spno2.accel");

class CompareDialogTest : public test::FileDialogsFixture
{
protected:
    bool compare(CompareDialog& dialog)
    {
        bool ok = false;
        QObject::connect(&dialog, &CompareDialog::compareFinished, &dialog,
                         [&ok](bool r) { ok = r; });
        EXPECT_TRUE(runUntil(&dialog, &CompareDialog::compareFinished, [&] { dialog.compare(); }));
        return ok;
    }
};

} // namespace

TEST_F(CompareDialogTest, DriveAgainstFileShowsOnlyTheChangedSettingAsDifferent)
{
    start(QStringLiteral("dbu200@1"), {1});
    setRegister(1, address(kDbu, kAccel), 25);
    const QString file = path(QStringLiteral("drive1.json"));
    ASSERT_TRUE(backUp({1}, file));
    setRegister(1, address(kDbu, kAccel), 123);

    CompareDialog dialog(drives.get());
    dialog.setDriveSide(CompareDialog::A, 1);
    ASSERT_TRUE(dialog.setFileSide(CompareDialog::B, file)) << qPrintable(dialog.errorText());
    ASSERT_TRUE(compare(dialog)) << qPrintable(dialog.errorText());
    EXPECT_EQ(dialog.differences(), QStringList{kAccel});
    EXPECT_TRUE(dialog.isHighlighted(kAccel));
    EXPECT_FALSE(dialog.isHighlighted(QStringLiteral("spno2.decel")));
    EXPECT_EQ(dialog.cellText(kAccel, CompareDialog::ValueA), QStringLiteral("12.3 s"));
    EXPECT_EQ(dialog.cellText(kAccel, CompareDialog::ValueB), QStringLiteral("2.5 s"));
    EXPECT_GT(dialog.rowCount(), 10);
    EXPECT_EQ(dialog.visibleRowCount(), dialog.rowCount());

    dialog.setDifferencesOnly(true);
    EXPECT_EQ(dialog.visibleRowCount(), 1);
    EXPECT_TRUE(dialog.isRowShown(kAccel));
    dialog.setDifferencesOnly(false);
    dialog.setFilterText(QStringLiteral("spno2.dec"));
    EXPECT_FALSE(dialog.isRowShown(kAccel));
    EXPECT_TRUE(dialog.isRowShown(QStringLiteral("spno2.decel")));
}

TEST_F(CompareDialogTest, DriveAgainstFactoryDefaultsMatchesTheComparer)
{
    start(QStringLiteral("dbu200@1"), {1});
    setRegister(1, address(kDbu, kAccel), 123); // the default is 0.5 s
    CompareDialog dialog(drives.get());
    dialog.setDriveSide(CompareDialog::A, 1);
    dialog.setDefaultsSide();
    ASSERT_TRUE(compare(dialog)) << qPrintable(dialog.errorText());
    EXPECT_TRUE(dialog.differences().contains(kAccel));
    EXPECT_TRUE(dialog.isHighlighted(kAccel));
    EXPECT_EQ(dialog.cellText(kAccel, CompareDialog::ValueB), QStringLiteral("0.5 s"));
    // The dialog shows what the comparer finds, nothing more or less.
    const QString file = path(QStringLiteral("drive1.json"));
    ASSERT_TRUE(backUp({1}, file));
    QString error;
    const auto loaded = BackupFile::load(file, ProfileRegistry::builtIn(), &error);
    ASSERT_TRUE(loaded);
    const Comparer::Result expected =
        Comparer::compareWithDefaults(*ProfileRegistry::builtIn().family(kDbu), *loaded->device(1));
    EXPECT_EQ(dialog.differences().size(), expected.differences.size());
    ASSERT_FALSE(expected.noDefault.isEmpty());
    // Named by the label a user knows, not the internal name.
    const ParameterMeta* first =
        ProfileRegistry::builtIn().family(kDbu)->parameter(expected.noDefault.first());
    ASSERT_NE(first, nullptr);
    EXPECT_TRUE(dialog.notesText().contains(first->label)) << qPrintable(dialog.notesText());
    EXPECT_FALSE(dialog.notesText().contains(expected.noDefault.first()))
        << qPrintable(dialog.notesText());
}

TEST_F(CompareDialogTest, FilesOfDifferentFamiliesAreRefusedWithTheReason)
{
    start(QStringLiteral("dbu200@1,dcpid@5"), {1, 5});
    const QString file = path(QStringLiteral("bus.json"));
    ASSERT_TRUE(backUp({1, 5}, file));
    CompareDialog dialog(drives.get());
    ASSERT_TRUE(dialog.setFileSide(CompareDialog::A, file, 1));
    ASSERT_TRUE(dialog.setFileSide(CompareDialog::B, file, 5));
    EXPECT_FALSE(compare(dialog));
    EXPECT_FALSE(dialog.errorText().isEmpty());
    EXPECT_EQ(dialog.rowCount(), 0);
}

TEST_F(CompareDialogTest, ARefusedFileSaysWhy)
{
    start(QStringLiteral("dbu200@1"), {1});
    const QString garbage = path(QStringLiteral("garbage.json"));
    writeFile(garbage, "[1, 2");
    CompareDialog dialog(drives.get());
    EXPECT_FALSE(dialog.setFileSide(CompareDialog::B, garbage));
    EXPECT_TRUE(dialog.errorText().contains(QStringLiteral("JSON")))
        << qPrintable(dialog.errorText());
}
