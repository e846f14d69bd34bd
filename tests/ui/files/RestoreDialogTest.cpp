#include "ui/files/RestoreDialog.h"
#include "tests/ui/files/FileDialogsFixture.h"

#include <QAbstractButton>
#include <QApplication>
#include <QMessageBox>
#include <QPushButton>

using namespace opentop;

namespace {

const QString kDbu = QStringLiteral("dbu");
const QString kAccel = QStringLiteral("spno2.accel");
const QString kDecel = QStringLiteral("spno2.decel");
using Item = RestorePlan::Item;

class RestoreDialogTest : public test::FileDialogsFixture
{
protected:
    // The parameters the plans of the dialog would write (or wrote).
    static QStringList toWrite(const RestoreDialog& dialog)
    {
        QStringList names;
        for (const RestorePlan& plan : dialog.plans()) {
            for (const Item& item : plan.items) {
                if (item.action == Item::Action::Write)
                    names << item.parameter;
            }
        }
        return names;
    }

    bool preview(RestoreDialog& dialog)
    {
        return runUntil(&dialog, &RestoreDialog::previewFinished, [&] { dialog.preview(); });
    }

    // Drive 1 backed up with SPno2 times 2.5 s / 3.0 s (raw 25, 30), then both changed on the
    // drive (123, 45). Returns the file.
    QString backUpThenChangeBoth()
    {
        start(QStringLiteral("dbu200@1"), {1});
        const quint16 accel = address(kDbu, kAccel);
        const quint16 decel = address(kDbu, kDecel);
        setRegister(1, accel, 25);
        setRegister(1, decel, 30);
        const QString file = path(QStringLiteral("drive1.json"));
        EXPECT_TRUE(backUp({1}, file));
        setRegister(1, accel, 123);
        setRegister(1, decel, 45);
        return file;
    }

    bool write(RestoreDialog& dialog)
    {
        return runUntil(&dialog, &RestoreDialog::writeFinished,
                        [&] { EXPECT_TRUE(dialog.write()); });
    }
};

} // namespace

TEST_F(RestoreDialogTest, RestoresAChangedSettingAndVerifiesIt)
{
    start(QStringLiteral("dbu200@1"), {1});
    const quint16 accel = address(kDbu, kAccel);
    setRegister(1, accel, 25);
    const QString file = path(QStringLiteral("drive1.json"));
    ASSERT_TRUE(backUp({1}, file));
    setRegister(1, accel, 123); // changed on the drive after the backup

    RestoreDialog dialog(drives.get());
    ASSERT_TRUE(dialog.setPath(file)) << qPrintable(dialog.errorText());
    EXPECT_EQ(dialog.target(1), 1);
    EXPECT_FALSE(dialog.canWrite()); // never without a preview
    const int writes = writesSent();
    ASSERT_TRUE(preview(dialog));
    EXPECT_EQ(writesSent(), writes); // a preview only reads
    EXPECT_EQ(toWrite(dialog), QStringList{kAccel});
    EXPECT_EQ(dialog.cellText(1, kAccel, RestoreDialog::Column::Action), QStringLiteral("write"))
        << qPrintable(dialog.cellText(1, kAccel, RestoreDialog::Column::Action));
    EXPECT_EQ(dialog.cellText(1, kAccel, RestoreDialog::Column::FileValue),
              QStringLiteral("2.5 s"));
    EXPECT_EQ(dialog.cellText(1, kAccel, RestoreDialog::Column::DriveValue),
              QStringLiteral("12.3 s"));
    EXPECT_EQ(simRegister(1, accel), 123);
    ASSERT_TRUE(dialog.canWrite());

    ASSERT_TRUE(write(dialog));
    ASSERT_EQ(dialog.plans().size(), 1);
    EXPECT_EQ(dialog.plans().first().outcome, RestorePlan::Outcome::Done)
        << qPrintable(dialog.outcomeText());
    EXPECT_EQ(dialog.plans().first().count(Item::Status::Verified), 1);
    EXPECT_FALSE(dialog.isMismatchHighlighted(1, kAccel));
    EXPECT_EQ(dialog.cellText(1, kAccel, RestoreDialog::Column::Result),
              QStringLiteral("written and verified"));
    EXPECT_EQ(simRegister(1, accel), 25);
    EXPECT_TRUE(dialog.reportText().contains(kAccel));

    QString error;
    const QString report = path(QStringLiteral("report.csv"));
    ASSERT_TRUE(dialog.saveReport(report, &error)) << qPrintable(error);
    const QByteArray csv = readFile(report);
    EXPECT_TRUE(csv.startsWith("slave,drive,outcome,parameter")) << csv.constData();
    EXPECT_TRUE(csv.contains("spno2.accel,write,verified")) << csv.constData();
}

TEST_F(RestoreDialogTest, WritesOnlyTheChosenParameters)
{
    const QString file = backUpThenChangeBoth();
    const quint16 accel = address(kDbu, kAccel);
    const quint16 decel = address(kDbu, kDecel);

    RestoreDialog dialog(drives.get());
    ASSERT_TRUE(dialog.setPath(file));
    dialog.setParameters(1, {kDecel});
    ASSERT_TRUE(preview(dialog));
    EXPECT_EQ(toWrite(dialog), QStringList{kDecel});
    ASSERT_TRUE(write(dialog));
    EXPECT_EQ(dialog.plans().first().outcome, RestorePlan::Outcome::Done);
    EXPECT_EQ(simRegister(1, decel), 30);
    EXPECT_EQ(simRegister(1, accel), 123); // not chosen: left as the drive has it
}

TEST_F(RestoreDialogTest, ChangingTheChoiceAfterAPreviewNeedsANewPreview)
{
    start(QStringLiteral("dbu200@1"), {1});
    const QString file = path(QStringLiteral("drive1.json"));
    ASSERT_TRUE(backUp({1}, file));
    RestoreDialog dialog(drives.get());
    ASSERT_TRUE(dialog.setPath(file));
    ASSERT_TRUE(preview(dialog));
    EXPECT_TRUE(dialog.canWrite());
    dialog.setParameters(1, {kAccel});
    EXPECT_FALSE(dialog.canWrite());
    EXPECT_FALSE(dialog.write());
}

TEST_F(RestoreDialogTest, RefusesAChangedOrNonJsonFileAndSendsNothing)
{
    start(QStringLiteral("dbu200@1"), {1});
    const QString file = path(QStringLiteral("drive1.json"));
    ASSERT_TRUE(backUp({1}, file));
    QByteArray data = readFile(file);
    const int at = int(data.indexOf("\"registers\": [")) + 14;
    ASSERT_GT(at, 14);
    data.insert(at, '1'); // a register edited by hand
    const QString changed = path(QStringLiteral("changed.json"));
    writeFile(changed, data);
    const QString garbage = path(QStringLiteral("garbage.json"));
    writeFile(garbage, "{ not json");
    const int writes = writesSent();
    const int frames = framesSent();

    for (const QString& bad : {changed, garbage}) {
        RestoreDialog dialog(drives.get());
        EXPECT_FALSE(dialog.setPath(bad));
        EXPECT_FALSE(dialog.errorText().isEmpty());
        EXPECT_TRUE(dialog.outcomeText().contains(dialog.errorText()));
        EXPECT_TRUE(dialog.outcomeText().contains(QStringLiteral("nothing will be written")));
        EXPECT_TRUE(preview(dialog));
        EXPECT_TRUE(dialog.outcomeText().contains(dialog.errorText()));
        EXPECT_FALSE(dialog.canWrite());
        EXPECT_FALSE(dialog.write());
    }
    EXPECT_EQ(writesSent(), writes);
    EXPECT_EQ(framesSent(), frames); // not even read
}

TEST_F(RestoreDialogTest, RefusesADcControllerFileOnADbuWithTheReason)
{
    start(QStringLiteral("dbu200@1,dcpid@5"), {1, 5});
    const QString file = path(QStringLiteral("dc.json"));
    ASSERT_TRUE(backUp({5}, file));
    RestoreDialog dialog(drives.get());
    ASSERT_TRUE(dialog.setPath(file));
    dialog.setTarget(5, 1);
    ASSERT_EQ(dialog.target(5), 1);
    const int writes = writesSent();
    ASSERT_TRUE(preview(dialog));
    ASSERT_EQ(dialog.plans().size(), 1);
    EXPECT_TRUE(dialog.plans().first().refused());
    EXPECT_FALSE(dialog.plans().first().reason.isEmpty());
    EXPECT_TRUE(dialog.outcomeText().contains(dialog.plans().first().reason))
        << qPrintable(dialog.outcomeText());
    EXPECT_TRUE(dialog.outcomeText().contains(QStringLiteral("nothing written")));
    EXPECT_FALSE(dialog.canWrite());
    EXPECT_FALSE(dialog.write());
    EXPECT_EQ(writesSent(), writes);
}

TEST_F(RestoreDialogTest, ClosingWhileWritingCancelsAndReportsWhatWasWritten)
{
    const QString file = backUpThenChangeBoth();
    const quint16 accel = address(kDbu, kAccel);
    const quint16 decel = address(kDbu, kDecel);

    RestoreDialog dialog(drives.get());
    dialog.show();
    ASSERT_TRUE(dialog.setPath(file));
    ASSERT_TRUE(preview(dialog));
    ASSERT_EQ(toWrite(dialog).size(), 2);
    bool finished = false;
    QObject::connect(&dialog, &RestoreDialog::writeFinished, &dialog, [&] { finished = true; });
    // The window's close button once the first write has been verified.
    QObject::connect(&dialog, &RestoreDialog::progress, &dialog, [&](int, int done, int) {
        if (done == 1) {
            dialog.reject();
            EXPECT_TRUE(dialog.isVisible());
        }
    });
    ASSERT_TRUE(dialog.write());
    ASSERT_TRUE(waitUntil([&] { return finished; }));
    EXPECT_TRUE(dialog.isVisible());
    const RestorePlan& plan = dialog.plans().first();
    EXPECT_EQ(plan.outcome, RestorePlan::Outcome::Interrupted);
    EXPECT_EQ(plan.count(Item::Status::Verified), 1);
    EXPECT_EQ(plan.count(Item::Status::NotAttempted), 1);
    EXPECT_TRUE(dialog.reportText().contains(QStringLiteral("not attempted")));
    // Exactly one of the two settings is back.
    EXPECT_EQ((simRegister(1, accel) == 25) + (simRegister(1, decel) == 30), 1);
}

TEST_F(RestoreDialogTest, AFileThatSetsTheSerialLockSaysSoInTheQuestion)
{
    // A DC controller backed up with its serial configuration lock on, restored to one without:
    // the question before writing says what the lock does and how to undo it; Cancel sends
    // nothing.
    start(QStringLiteral("dcpid@5"), {5});
    const quint16 lock = address(QStringLiteral("dcpid"), QStringLiteral("config.serial_lock"));
    setRegister(5, lock, 1);
    const QString file = path(QStringLiteral("locked.json"));
    ASSERT_TRUE(backUp({5}, file));
    setRegister(5, lock, 0);
    RestoreDialog dialog(drives.get());
    ASSERT_TRUE(dialog.setPath(file)) << qPrintable(dialog.errorText());
    ASSERT_TRUE(preview(dialog));
    ASSERT_TRUE(toWrite(dialog).contains(QStringLiteral("config.serial_lock")));
    QPushButton* writeButton = nullptr;
    for (auto* b : dialog.findChildren<QPushButton*>())
        if (b->text() == QStringLiteral("&Write to drives…"))
            writeButton = b;
    ASSERT_TRUE(writeButton);
    EXPECT_TRUE(dialog.canWrite());
    ASSERT_TRUE(writeButton->isEnabled()) << qPrintable(dialog.outcomeText());
    const int writes = writesSent();
    writeButton->click();
    auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
    ASSERT_TRUE(box);
    EXPECT_TRUE(box->text().contains(QStringLiteral(
        "Drive 5: Serial configuration lock = Disabled (1) prohibits configuration")))
        << qPrintable(box->text());
    EXPECT_TRUE(box->text().contains(QStringLiteral("9600"))) << qPrintable(box->text());
    box->button(QMessageBox::Cancel)->click();
    QCoreApplication::processEvents();
    EXPECT_EQ(writesSent(), writes);
    EXPECT_EQ(simRegister(5, lock), 0);
}
