// A laptop in real use (issue 24 item 7): a maximised window on a real desktop is about
// 1366×700, and an engineer keeps docks open beside the pages. Every page of every family is
// inspected beside no dock, each dock alone and every dock together, at 1366×700 and 1366×768;
// what a user must reach (STOP ALL, the test run's commands, the drive's display) must be in
// sight, charts must keep their axes, and the windows the menus open must leave STOP ALL visible.
#include "tests/ui/main/MainWindowLayoutFixture.h"
#include "ui/eol/RecipeEditor.h"
#include "ui/files/RestoreDialog.h"

#include <QDockWidget>
#include <QHeaderView>
#include <QTemporaryDir>

using namespace opentop;
using namespace opentop::test;

namespace {

struct DockSet
{
    QString name;
    QList<QDockWidget*> docks;
};

} // namespace

class MainWindowDockLayoutTest : public MainWindowLayoutTest
{
protected:
    // The window as tall as `height` on a screen of that height.
    void resizeTo(int height)
    {
        screen = QRect(screen.topLeft(), QSize(1366, height));
        window->setGeometry(screen);
        settle();
    }

    QList<DockSet> dockSets() const
    {
        const QList<QDockWidget*> docks = window->findChildren<QDockWidget*>();
        QList<DockSet> sets{{QStringLiteral("no dock"), {}}};
        for (QDockWidget* dock : docks)
            sets << DockSet{QStringLiteral("dock %1").arg(dock->windowTitle()), {dock}};
        sets << DockSet{QStringLiteral("every dock"), docks};
        return sets;
    }

    void showDocks(const DockSet& set)
    {
        for (QDockWidget* dock : window->findChildren<QDockWidget*>())
            dock->setVisible(set.docks.contains(dock));
        settle(200);
    }

    // The STOP ALL button's place on the screen.
    QRect stopAllOnScreen() const
    {
        const QWidget* stop = window->stopAllButton();
        return QRect(stop->mapToGlobal(QPoint(0, 0)), stop->size());
    }

    void expectStopAllVisibleBeside(QWidget* dialog, const QString& where)
    {
        if (dialog->frameGeometry().intersects(stopAllOnScreen()))
            problems << QStringLiteral("[%1] the window at %2 covers STOP ALL at %3")
                            .arg(where, QString::fromStdString(rect(dialog->frameGeometry())),
                                 QString::fromStdString(rect(stopAllOnScreen())));
    }
};

TEST_F(MainWindowDockLayoutTest, EveryPageBesideEveryDockFitsALaptopWindow)
{
    window->monitorAll();
    for (int height : {700, 768}) {
        resizeTo(height);
        for (const DockSet& set : dockSets()) {
            showDocks(set);
            const QString at = QStringLiteral("1366×%1, %2").arg(height).arg(set.name);
            inspectPages(1, at + QStringLiteral(", DBU200 1"));
            inspectPages(150, at + QStringLiteral(", DBU400 150"));
            inspectPages(7, at + QStringLiteral(", DC controller 7"));
            explainHeight();
        }
    }
    EXPECT_TRUE(problems.isEmpty()) << qPrintable(report());
}

TEST_F(MainWindowDockLayoutTest, TheBusListShowsEveryColumnWhole)
{
    resizeTo(700);
    for (const DockSet& set : dockSets()) {
        showDocks(set);
        settle(500); // the columns sized to what the drives reported
        QTableView* view = window->busPanel()->view();
        QHeaderView* header = view->horizontalHeader();
        for (int c = 0; c < header->count(); ++c) {
            if (header->isSectionHidden(c))
                continue;
            const int right = header->sectionViewportPosition(c) + header->sectionSize(c);
            if (right > view->viewport()->width())
                problems << QStringLiteral("[%1] bus list column \"%2\" ends at %3 px of %4")
                                .arg(set.name,
                                     view->model()->headerData(c, Qt::Horizontal).toString())
                                .arg(right)
                                .arg(view->viewport()->width());
        }
        for (const QString& cell : LayoutInspector::cutCells(view))
            problems << QStringLiteral("[%1] bus list cell %2").arg(set.name, cell);
    }
    EXPECT_TRUE(problems.isEmpty()) << qPrintable(report());
}

TEST_F(MainWindowDockLayoutTest, PausedPollingKeepsTheWindowInsideTheScreen)
{
    resizeTo(700);
    showDocks(dockSets().last());
    select({1});
    ASSERT_TRUE(
        waitFor([&] { return window->workspace()->drive() == window->drives()->parameters(1); }));
    window->workspace()->tabs()->setCurrentIndex(0);
    window->monitorHub()->setPaused(true);
    settle(300);
    inspect(window.get(), QStringLiteral("1366×700, every dock, polling paused"));
    explainHeight();
    EXPECT_LE(window->frameGeometry().width(), 1366);
    window->monitorHub()->setPaused(false);
    EXPECT_TRUE(problems.isEmpty()) << qPrintable(report());
}

TEST_F(MainWindowDockLayoutTest, TheConnectionDialogWithAdvancedOpenFits)
{
    resizeTo(700);
    bool seen = false;
    QTimer poll;
    poll.setInterval(30);
    QObject::connect(&poll, &QTimer::timeout, [&] {
        auto* dialog = qobject_cast<QDialog*>(QApplication::activeModalWidget());
        if (!dialog || !dialog->isVisible())
            return;
        poll.stop();
        for (QAbstractButton* b : dialog->findChildren<QAbstractButton*>()) {
            if (b->isCheckable() && !b->isChecked() &&
                translationsOf(language, QStringLiteral("&Advanced")).contains(b->text()))
                b->click();
        }
        settle(200);
        inspect(dialog, QStringLiteral("connection dialog, Advanced open"));
        seen = true;
        dialog->reject();
    });
    poll.start();
    action(QStringLiteral("Connect"))->trigger();
    poll.stop();
    EXPECT_TRUE(seen);
    EXPECT_TRUE(problems.isEmpty()) << qPrintable(report());
}

TEST_F(MainWindowDockLayoutTest, WindowsTheMenusOpenLeaveStopAllVisible)
{
    resizeTo(700);
    select({1});
    settle();
    action(QStringLiteral("Compare"))->trigger();
    settle(300);
    QDialog* compare = nullptr;
    for (QDialog* d : window->findChildren<QDialog*>(QString(), Qt::FindDirectChildrenOnly)) {
        if (d->inherits("opentop::CompareDialog") && d->isVisible())
            compare = d;
    }
    ASSERT_NE(compare, nullptr);
    inspect(compare, QStringLiteral("compare at 1366×700"));
    expectStopAllVisibleBeside(compare, QStringLiteral("compare"));
    compare->close();

    // Restore and the recipe editor, opened as their actions open them.
    QTemporaryDir dir;
    auto* restore = new RestoreDialog(window->drives(), window.get());
    restore->show();
    settle(300);
    inspect(restore, QStringLiteral("restore at 1366×700"));
    expectStopAllVisibleBeside(restore, QStringLiteral("restore"));
    restore->close();
    auto* editor = new RecipeEditor([this] { return window->drives(); }, window.get());
    editor->show();
    settle(300);
    inspect(editor, QStringLiteral("recipe editor at 1366×700"));
    expectStopAllVisibleBeside(editor, QStringLiteral("recipe editor"));
    editor->close();
    EXPECT_TRUE(problems.isEmpty()) << qPrintable(report());
}
