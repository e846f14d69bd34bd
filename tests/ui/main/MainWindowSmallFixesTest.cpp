// Issue 24 item 8, the small ones, in the real window: the Test run page's SPno beside what the
// drive runs, the running data grid that does not move under the mouse, a refusal that goes
// with its cause, Compare's file drive following side A, the restore preview's filter and its
// store commands, the trend that has no gap behind another page, alarm remedies that name
// settings, and the keyboard shortcuts' list.
#include "tests/ui/main/MainWindowFixture.h"

#include "model/session/Freshness.h"
#include "ui/alarms/AlarmBanner.h"
#include "ui/files/BackupDialog.h"
#include "ui/files/CompareDialog.h"
#include "ui/files/RestoreDialog.h"
#include "ui/help/ShortcutsDialog.h"
#include "ui/pages/RunningDataPage.h"
#include "ui/run/RunLiveState.h"
#include "ui/run/SpnoSelector.h"

#include <QCheckBox>
#include <QComboBox>
#include <QLineEdit>
#include <QMenuBar>
#include <QTemporaryDir>

using namespace opentop;
using namespace opentop::test;

namespace {

class MainWindowSmallFixesTest : public MainWindowFixture
{
protected:
    // The current drive's page of type T, made current.
    template <typename T> T* showPage(int slave)
    {
        select({slave});
        T* page = nullptr;
        waitFor([&] {
            if (window->workspace()->drive() != window->drives()->parameters(slave))
                return false;
            QTabWidget* tabs = window->workspace()->tabs();
            for (int i = 0; i < tabs->count() && !page; ++i) {
                page = qobject_cast<T*>(tabs->widget(i));
                if (!page)
                    page = tabs->widget(i)->findChild<T*>();
                if (page)
                    tabs->setCurrentIndex(i);
            }
            return page != nullptr;
        });
        return page;
    }

    QAction* menuAction(const QString& text)
    {
        for (QAction* a : window->findChildren<QAction*>()) {
            if (a->text() == text)
                return a;
        }
        return nullptr;
    }

    // Backs up `slaves` to `path` the way Files ▸ Back up makes its dialog.
    void backUp(const QVector<int>& slaves, const QString& path)
    {
        auto* backup = new BackupDialog(window->drives(), ConnectionSettings(), window.get());
        bool saved = false;
        QObject::connect(backup, &BackupDialog::backupFinished, [&](bool ok) { saved = ok; });
        backup->show();
        backup->startBackup(slaves, path);
        ASSERT_TRUE(waitFor([&] { return saved; }, 30000));
        backup->close();
    }

    int framesTo(int slave, quint8 function)
    {
        int n = 0;
        for (const TrafficEntry& e : window->trafficLog()->entries())
            n += e.direction == TrafficEntry::Direction::Tx && e.slave == slave &&
                         e.function == function
                     ? 1
                     : 0;
        return n;
    }
};

} // namespace

TEST_F(MainWindowSmallFixesTest, TheTestRunPageShowsTheRunningDataTheDriveRuns)
{
    // The drive runs SPno4 (selected over the bus before this program started).
    bus->control(1, {QStringLiteral("set"), QStringLiteral("0x100D"), QStringLiteral("2")});
    bus->control(1, {QStringLiteral("set"), QStringLiteral("0x200F"), QStringLiteral("3")});
    TestRunPanel* panel = showPage<TestRunPanel>(1);
    ASSERT_NE(panel, nullptr);
    SpnoSelector* spno = panel->spnoSelector();
    ASSERT_NE(spno, nullptr);
    // What the drive runs, live, in its own row...
    ASSERT_TRUE(waitFor([&] {
        return panel->liveState()->runningDataText() == QStringLiteral("SPno4");
    })) << qPrintable(panel->liveState()->runningDataText());
    // ...and the selector, not yet touched, starts at it rather than at SPno1.
    ASSERT_TRUE(waitFor([&] { return spno->driveSpno() == 4; }));
    EXPECT_EQ(spno->currentData().toInt(), 4);
    EXPECT_TRUE(spno->toolTip().contains(QStringLiteral("The drive reported SPno4")));
    // The user's choice is the user's: what the drive reports later does not move it.
    spno->setCurrentIndex(spno->findData(6));
    emit spno->activated(spno->currentIndex());
    bus->control(1, {QStringLiteral("set"), QStringLiteral("0x200F"), QStringLiteral("1")});
    ASSERT_TRUE(
        waitFor([&] { return panel->liveState()->runningDataText() == QStringLiteral("SPno2"); }));
    panel->refresh();
    ASSERT_TRUE(waitFor([&] { return spno->driveSpno() == 2; }));
    EXPECT_EQ(spno->currentData().toInt(), 6);
}

TEST_F(MainWindowSmallFixesTest, AMessageInTheRunningDataGridDoesNotMoveTheRows)
{
    auto* page = showPage<RunningDataPage>(1);
    ASSERT_NE(page, nullptr);
    ASSERT_TRUE(waitFor([&] {
        return window->drives()->parameters(1)->entry(QStringLiteral("spno2.speed"))->device.valid;
    }));
    QTest::qWait(100);
    auto rowTops = [&] {
        QVector<int> tops;
        for (int spno = 3; spno <= 8; ++spno) {
            ParameterField* f = page->field(QStringLiteral("spno%1.speed").arg(spno));
            tops << f->mapTo(page, QPoint(0, 0)).y();
        }
        tops << page->initializeButton(8)->mapTo(page, QPoint(0, 0)).y();
        return tops;
    };
    const QVector<int> before = rowTops();
    // A refused value, typed and confirmed; then a warning from another row.
    page->field(QStringLiteral("spno2.speed"))->enter(QStringLiteral("5000"));
    page->field(QStringLiteral("spno5.speed"))->enter(QStringLiteral("9999"));
    QTest::qWait(100);
    EXPECT_EQ(rowTops(), before) << "the rows stayed where they were";
    const QString messages = page->fieldMessages();
    EXPECT_TRUE(messages.contains(QStringLiteral("SPno2 speed: Not accepted")))
        << qPrintable(messages);
    EXPECT_TRUE(messages.contains(QStringLiteral("SPno5 speed: Not accepted")))
        << qPrintable(messages);
    auto* line = page->findChild<QLabel*>(QStringLiteral("fieldMessages"));
    ASSERT_NE(line, nullptr);
    EXPECT_TRUE(line->isVisible());
    // Reverted: the message goes, and the rows still do not move.
    page->revertPage();
    QTest::qWait(100);
    EXPECT_TRUE(page->fieldMessages().isEmpty()) << qPrintable(page->fieldMessages());
    EXPECT_EQ(rowTops(), before);
}

TEST_F(MainWindowSmallFixesTest, NothingWasWrittenGoesOnceTheFieldIsFixed)
{
    auto* page = showPage<RunningDataPage>(1);
    ASSERT_NE(page, nullptr);
    ASSERT_TRUE(waitFor([&] {
        return window->drives()->parameters(1)->entry(QStringLiteral("spno2.speed"))->device.valid;
    }));
    page->field(QStringLiteral("spno2.speed"))->enter(QStringLiteral("5000"));
    page->writePage();
    EXPECT_TRUE(page->statusText().startsWith(QStringLiteral("Nothing was written")))
        << qPrintable(page->statusText());
    // The same from Write all pending, in the workspace's own line.
    window->workspace()->writeAll();
    auto statusOf = [&] {
        QString texts;
        for (QLabel* l :
             window->workspace()->findChildren<QLabel*>(QString(), Qt::FindDirectChildrenOnly))
            texts += l->text() + QLatin1Char('\n');
        return texts;
    };
    EXPECT_TRUE(statusOf().contains(QStringLiteral("Nothing was written")))
        << qPrintable(statusOf());
    // Fixed: neither line still says what stopped the earlier click.
    page->field(QStringLiteral("spno2.speed"))->enter(QStringLiteral("2200"));
    EXPECT_FALSE(page->statusText().contains(QStringLiteral("Nothing was written")))
        << qPrintable(page->statusText());
    EXPECT_TRUE(page->statusText().contains(QStringLiteral("Every field is accepted now")))
        << qPrintable(page->statusText());
    EXPECT_FALSE(statusOf().contains(QStringLiteral("Nothing was written")))
        << qPrintable(statusOf());
    EXPECT_TRUE(statusOf().contains(QStringLiteral("Every edit is accepted now")));
    // Reverted instead: nothing left to say.
    page->revertPage();
    EXPECT_TRUE(page->statusText().isEmpty()) << qPrintable(page->statusText());
}

TEST_F(MainWindowSmallFixesTest, ComparesDriveInFileFollowsSideAsDrive)
{
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("bus.json"));
    backUp({1, 7}, file);
    select({7});
    QAction* compare = menuAction(QStringLiteral("Co&mpare…"));
    ASSERT_NE(compare, nullptr);
    compare->trigger();
    CompareDialog* dialog = nullptr;
    ASSERT_TRUE(waitFor([&] {
        dialog = window->findChild<CompareDialog*>();
        return dialog && dialog->isVisible();
    }));
    // Side A is drive 7 (the selected one); side B gets the file: its drive 7, not its first.
    ASSERT_TRUE(dialog->setFileSide(CompareDialog::B, file));
    CompareSide* sideB = nullptr;
    for (CompareSide* s : dialog->findChildren<CompareSide*>())
        sideB = s->QGroupBox::title() == QStringLiteral("Side B") ? s : sideB;
    ASSERT_NE(sideB, nullptr);
    EXPECT_EQ(sideB->shownSlave(), 7);
    // Side A changes to drive 1: the file's drive follows.
    dialog->setDriveSide(CompareDialog::A, 1);
    EXPECT_EQ(sideB->shownSlave(), 1);
    bool done = false;
    QObject::connect(dialog, &CompareDialog::compareFinished, [&](bool) { done = true; });
    dialog->compare();
    ASSERT_TRUE(waitFor([&] { return done; }, 20000));
    EXPECT_TRUE(dialog->differences().isEmpty())
        << "a drive against its own backup: "
        << qPrintable(dialog->differences().join(QLatin1Char(',')));
    dialog->close();
}

TEST_F(MainWindowSmallFixesTest, TheRestorePreviewFiltersDifferencesAndStoresOnlyWhatNeedsIt)
{
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("dc.json"));
    backUp({7}, file);
    auto* restore = new RestoreDialog(window->drives(), window.get());
    restore->setAttribute(Qt::WA_DeleteOnClose);
    restore->show();
    ASSERT_TRUE(restore->setPath(file));
    auto preview = [&] {
        bool previewed = false;
        QObject::connect(
            restore, &RestoreDialog::previewFinished, restore, [&] { previewed = true; },
            Qt::SingleShotConnection);
        restore->preview();
        return waitFor([&] { return previewed; }, 20000);
    };
    // Unchanged: every row kept, no store command planned, and the notes say why.
    ASSERT_TRUE(preview());
    ASSERT_EQ(restore->plans().size(), 1);
    EXPECT_EQ(restore->plans().first().count(RestorePlan::Item::Action::Store), 0);
    EXPECT_TRUE(restore->plans()
                    .first()
                    .notes.join(QLatin1Char(' '))
                    .contains(QStringLiteral("not sent: nothing it stores is written")));
    const int all = restore->table()->shownRows();
    EXPECT_GT(all, 10);
    restore->differencesOnlyBox()->setChecked(true);
    EXPECT_EQ(restore->table()->shownRows(), 0);
    // One PID setting differs: it and the PID store are what the filter shows.
    bus->control(7, {QStringLiteral("set"), QStringLiteral("0x0090"), QStringLiteral("16128")});
    ASSERT_TRUE(preview());
    EXPECT_EQ(restore->table()->shownRows(), 2);
    EXPECT_EQ(restore->cellText(7, QStringLiteral("store.pid"), RestoreDialog::Column::Action),
              QStringLiteral("store"));
    EXPECT_TRUE(restore->cellText(7, QStringLiteral("store.config"), RestoreDialog::Column::Action)
                    .isEmpty())
        << "the configuration is not touched, so not stored";
    restore->differencesOnlyBox()->setChecked(false);
    EXPECT_EQ(restore->table()->shownRows(), all + 1); // the planned store is a row of its own
    // Written: the PID value and its store, nothing else.
    const int writes = framesTo(7, 6) + framesTo(7, 16);
    bool written = false;
    QObject::connect(restore, &RestoreDialog::writeFinished, [&] { written = true; });
    ASSERT_TRUE(restore->write());
    ASSERT_TRUE(waitFor([&] { return written; }, 20000));
    EXPECT_EQ(framesTo(7, 6) + framesTo(7, 16) - writes, 2);
    EXPECT_EQ(restore->plans().first().outcome, RestorePlan::Outcome::Done);
    restore->close();
}

TEST_F(MainWindowSmallFixesTest, TheTrendHasNoGapWhileAnotherPageOfTheDriveIsShown)
{
    auto* monitor = showPage<MonitorPage>(1);
    ASSERT_NE(monitor, nullptr);
    MonitorHub* hub = window->monitorHub();
    hub->setInterval(200);
    auto series = [&] {
        const TrendHistory* h = hub->history(1);
        return h ? h->find(QStringLiteral("status.current_speed")) : nullptr;
    };
    ASSERT_TRUE(waitFor([&] { return series() && series()->points.size() >= 3; }));
    // A settings page in front for a while: nothing on it watches the drive.
    const qint64 left = QDateTime::currentMSecsSinceEpoch();
    window->workspace()->tabs()->setCurrentIndex(1);
    ASSERT_TRUE(waitFor([&] { return !hub->isWatched(1); }));
    QTest::qWait(3500);
    window->workspace()->tabs()->setCurrentWidget(monitor);
    ASSERT_TRUE(waitFor([&] { return hub->isWatched(1); }));
    QTest::qWait(600);
    // Points all through the time away, none farther apart than a value stays live.
    const QVector<TrendHistory::Point>& points = series()->points;
    int away = 0;
    for (int i = 1; i < points.size(); ++i) {
        EXPECT_LE(points[i].ms - points[i - 1].ms, Freshness::staleAfterMs(hub->interval()));
        away += points[i].ms > left + 500 && points[i].ms < left + 3400 ? 1 : 0;
    }
    EXPECT_GE(away, 2);
}

TEST_F(MainWindowSmallFixesTest, AnAlarmsRemedyNamesTheSettingNotItsAddress)
{
    select({1});
    ASSERT_TRUE(bus->control(1, {QStringLiteral("alarm"), QStringLiteral("7")}).ok);
    auto* banner = window->findChild<AlarmBanner*>();
    ASSERT_NE(banner, nullptr);
    ASSERT_TRUE(waitFor([&] { return banner->hasAlarm(); }));
    const QString text = banner->text();
    EXPECT_TRUE(
        text.contains(QStringLiteral("Overload alarm output time (Alarm/warning parameters)")))
        << qPrintable(text);
    EXPECT_FALSE(text.contains(QStringLiteral("0x1011"))) << qPrintable(text);
}

TEST_F(MainWindowSmallFixesTest, StopAllComesFirstAndEachShortcutIsUnderItsOwnMenu)
{
    const QVector<ShortcutsDialog::Entry> entries = ShortcutsDialog::collect(window.get());
    ASSERT_FALSE(entries.isEmpty());
    EXPECT_TRUE(entries.first().what.startsWith(QStringLiteral("STOP ALL")))
        << qPrintable(entries.first().what);
    bool groups = false;
    for (const ShortcutsDialog::Entry& e : entries) {
        if (!e.what.startsWith(QStringLiteral("Communication groups")))
            continue;
        groups = true;
        EXPECT_EQ(e.where, QStringLiteral("Bus")) << "the command is in the Bus menu";
        EXPECT_EQ(e.keys.value(0), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_G));
    }
    EXPECT_TRUE(groups);
    // And the key does what the Bus menu says.
    QDockWidget* dock = window->findChild<QDockWidget*>(QStringLiteral("groupsDock"));
    ASSERT_NE(dock, nullptr);
    dock->hide();
    QTest::keyClick(window.get(), Qt::Key_G, Qt::ControlModifier | Qt::ShiftModifier);
    EXPECT_TRUE(waitFor([&] { return dock->isVisible(); }));
}
