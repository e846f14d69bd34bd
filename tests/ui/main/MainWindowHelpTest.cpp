// Issue 10 item 15: the Help menu (user guide, keyboard shortcuts, About) and the traffic log's
// columns and statistics, in the program's window.
#include "tests/ui/main/MainWindowFixture.h"
#include "transport/LibraryVersions.h"
#include "ui/help/AboutDialog.h"
#include "ui/help/ShortcutsDialog.h"
#include "ui/help/UserGuideDialog.h"
#include "ui/traffic/TrafficLogModel.h"
#include "ui/traffic/TrafficLogView.h"

#include <QAction>
#include <QHeaderView>
#include <QMenuBar>
#include <QTableWidget>
#include <QTextBrowser>

using namespace opentop;
using namespace opentop::test;

using MainWindowHelpTest = MainWindowFixture;

namespace {

QAction* helpAction(QMainWindow* window, const QString& text)
{
    for (QAction* top : window->menuBar()->actions()) {
        if (!top->menu() || top->text() != QStringLiteral("&Help"))
            continue;
        for (QAction* a : top->menu()->actions()) {
            if (a->text().remove(QLatin1Char('&')) == text)
                return a;
        }
    }
    return nullptr;
}

template <typename Dialog> Dialog* shown(QWidget* window)
{
    for (Dialog* d : window->findChildren<Dialog*>()) {
        if (d->isVisible())
            return d;
    }
    return nullptr;
}

} // namespace

TEST_F(MainWindowHelpTest, TheShortcutsDialogListsEveryShortcutOfTheProgram)
{
    QAction* action = helpAction(window.get(), QStringLiteral("Keyboard shortcuts"));
    ASSERT_NE(action, nullptr);
    action->trigger();
    auto* dialog = shown<ShortcutsDialog>(window.get());
    ASSERT_NE(dialog, nullptr);
    QStringList keys;
    for (int row = 0; row < dialog->table()->rowCount(); ++row)
        keys << dialog->table()->item(row, 2)->text().split(QStringLiteral(" or "));
    // Every action of the window with a shortcut, whatever menu it is in.
    int withShortcut = 0;
    for (QAction* a : window->findChildren<QAction*>()) {
        for (const QKeySequence& k : a->shortcuts()) {
            ++withShortcut;
            EXPECT_TRUE(keys.contains(k.toString(QKeySequence::NativeText)))
                << qPrintable(a->text()) << " " << qPrintable(k.toString());
        }
    }
    EXPECT_GE(withShortcut, 10);
    // And STOP ALL's, which are not an action's.
    for (const QKeySequence& k : StopAllButton::shortcuts())
        EXPECT_TRUE(keys.contains(k.toString(QKeySequence::NativeText)))
            << qPrintable(k.toString());
    dialog->close();
}

TEST_F(MainWindowHelpTest, AboutNamesTheVersionAndTheLicences)
{
    QAction* action = helpAction(window.get(), QStringLiteral("About OpenTOP"));
    ASSERT_NE(action, nullptr);
    action->trigger();
    auto* about = shown<AboutDialog>(window.get());
    ASSERT_NE(about, nullptr);
    const QString text = about->text();
    EXPECT_TRUE(text.contains(QStringLiteral(OPENTOP_VERSION))) << qPrintable(text);
    EXPECT_TRUE(text.contains(QStringLiteral("GPL-3.0-or-later")));
    EXPECT_TRUE(text.contains(QString::fromLatin1(qVersion())));
    EXPECT_TRUE(text.contains(QStringLiteral("libmodbus ") + LibraryVersions::libmodbus()));
    EXPECT_TRUE(text.contains(QStringLiteral("LGPL-2.1-or-later")));
    about->close();
    // One dialog at a time: the action again shows the same kind, not a second one.
    action->trigger();
    action->trigger();
    int visible = 0;
    for (AboutDialog* d : window->findChildren<AboutDialog*>())
        visible += d->isVisible() ? 1 : 0;
    EXPECT_EQ(visible, 1);
}

TEST_F(MainWindowHelpTest, TheUserGuideOpensOnF1)
{
    QAction* action = helpAction(window.get(), QStringLiteral("User guide"));
    ASSERT_NE(action, nullptr);
    EXPECT_EQ(action->shortcut(), QKeySequence(QKeySequence::HelpContents));
    action->trigger();
    auto* guide = shown<UserGuideDialog>(window.get());
    ASSERT_NE(guide, nullptr);
    const QString text = guide->browser()->toPlainText();
    EXPECT_TRUE(text.contains(QStringLiteral("STOP ALL")));
    EXPECT_TRUE(text.contains(QStringLiteral("Scan bus")));
}

TEST_F(MainWindowHelpTest, TheTrafficLogShowsTheMeaningAndSummarisesAScansSilentAddresses)
{
    auto* view = window->findChild<TrafficLogView*>();
    ASSERT_NE(view, nullptr);
    window->findChild<QDockWidget*>(QStringLiteral("trafficDock"))->show();
    window->busPanel()->startScan(1, 30);
    ASSERT_TRUE(waitFor([&] { return !window->busPanel()->isScanning(); }, 30000));
    auto* stats = view->findChild<QTableWidget*>(QStringLiteral("trafficStatistics"));
    ASSERT_NE(stats, nullptr);
    ASSERT_TRUE(waitFor([&] {
        QTest::qWait(250); // the view refreshes in batches
        return view->statistics().unanswered().size() >= 27;
    }));
    QTest::qWait(300);
    // Drives 1, 2 and 7 (and 150, polled) answered; 3–6 and 8–30 in one line, not 27 rows.
    QStringList rows;
    for (int row = 0; row < stats->rowCount(); ++row)
        rows << stats->item(row, 0)->text();
    EXPECT_LE(stats->rowCount(), 6) << qPrintable(rows.join(QLatin1Char('|')));
    EXPECT_TRUE(rows.contains(QStringLiteral("1")));
    EXPECT_TRUE(rows.contains(QStringLiteral("7")));
    EXPECT_FALSE(rows.contains(QStringLiteral("5")));
    const QString summary = rows.first();
    EXPECT_TRUE(summary.contains(QStringLiteral("27 addresses did not answer")))
        << qPrintable(summary);
    EXPECT_TRUE(summary.contains(QStringLiteral("3–6, 8–30"))) << qPrintable(summary);

    // The meaning is the last column and has the width that is left.
    auto* table = view->findChild<QTableView*>(QStringLiteral("trafficTable"));
    ASSERT_NE(table, nullptr);
    QHeaderView* header = table->horizontalHeader();
    EXPECT_EQ(header->visualIndex(TrafficLogModel::Meaning), header->count() - 1);
    EXPECT_EQ(header->sectionViewportPosition(TrafficLogModel::Meaning) +
                  header->sectionSize(TrafficLogModel::Meaning),
              header->viewport()->width());
    EXPECT_GE(header->sectionSize(TrafficLogModel::Meaning), 400);
}
