// Laptop first (issue 10 item 13): the whole program on a 1366×768 screen. Every page of a DBU
// and of the DC controller, every dock and every dialog the menus open is shown in turn and
// inspected (LayoutInspector): nothing larger than the screen, nothing overlapping, no text cut.
#include "tests/ui/main/MainWindowLayoutFixture.h"
#include "ui/eol/RecipeEditor.h"
#include "ui/eol/ResultsBrowser.h"
#include "ui/files/BackupDialog.h"
#include "ui/files/BackupViewer.h"
#include "ui/files/RestoreDialog.h"
#include "ui/help/AboutDialog.h"
#include "ui/help/ShortcutsDialog.h"
#include "ui/help/UserGuideDialog.h"

#include <QAction>
#include <QDialog>
#include <QElapsedTimer>
#include <QHeaderView>
#include <QMenuBar>
#include <QScreen>
#include <QTemporaryDir>

using namespace opentop;
using namespace opentop::test;

TEST_F(MainWindowLayoutTest, TheDefaultWindowFitsTheScreen)
{
    // The offscreen screen is a laptop's (tests/support/offscreen-laptop.json).
    ASSERT_EQ(screen.size(), QSize(1366, 768));
    MainWindow fresh([](const ConnectionSettings&, TrafficLog*, QString*) {
        return std::unique_ptr<ModbusClient>();
    });
    EXPECT_LE(fresh.frameGeometry().width(), screen.width());
    EXPECT_LE(fresh.frameGeometry().height(), screen.height());
    EXPECT_TRUE(screen.contains(fresh.frameGeometry())) << rect(fresh.frameGeometry());
    // A geometry remembered on a larger screen is brought onto this one.
    QMainWindow big;
    big.setGeometry(100, 80, 1900, 1060);
    QSettings().setValue(QStringLiteral("mainWindow/geometry"), big.saveGeometry());
    MainWindow remembered([](const ConnectionSettings&, TrafficLog*, QString*) {
        return std::unique_ptr<ModbusClient>();
    });
    EXPECT_TRUE(screen.contains(remembered.frameGeometry())) << rect(remembered.frameGeometry());
}

TEST_F(MainWindowLayoutTest, EveryPageDockAndDialogFitsALaptopScreen)
{
    inspectEverything();
}

// The same walk in each language (issue 13): a translated label, button, tab or column header
// that does not fit the space it gets at 1366×768 fails here.
class MainWindowLanguageLayoutTest : public MainWindowLayoutTest,
                                     public ::testing::WithParamInterface<const char*>
{
protected:
    void SetUp() override
    {
        language = QString::fromLatin1(GetParam());
        MainWindowLayoutTest::SetUp();
    }
};

TEST_P(MainWindowLanguageLayoutTest, EveryPageDockAndDialogFitsALaptopScreen)
{
    ASSERT_EQ(Language::current(), language);
    if (ProfileRegistry::language() != language)
        GTEST_SKIP() << "the profiles were loaded in another language earlier in this process "
                        "(ctest runs each test in a process of its own)";
    // The device texts too: a DBU's core parameters page is named in the language.
    const ProfileGroup* core =
        ProfileRegistry::builtIn().family(QStringLiteral("dbu"))->group(QStringLiteral("core"));
    ASSERT_TRUE(core);
    EXPECT_NE(core->label, QStringLiteral("Core parameters"));
    // The window is in the language, not English with a few words changed.
    const QStringList busMenu = translationsOf(language, QStringLiteral("Bus"));
    ASSERT_FALSE(busMenu.isEmpty());
    EXPECT_TRUE(busMenu.contains(plainMenuText(window->menuBar()->actions().first()->text())))
        << qPrintable(window->menuBar()->actions().first()->text());
    inspectEverything();
}

INSTANTIATE_TEST_SUITE_P(Languages, MainWindowLanguageLayoutTest,
                         ::testing::Values("zh_TW", "zh_CN", "ko", "ja"),
                         [](const ::testing::TestParamInfo<const char*>& param) {
                             return std::string(param.param);
                         });

void MainWindowLayoutTest::inspectEverything()
{
    ASSERT_EQ(screen.size(), QSize(1366, 768));
    inspect(window.get(), QStringLiteral("after connecting"));
    // The bus list shows which drive, its state and its control priority without scrolling.
    QHeaderView* busHeader = window->busPanel()->view()->horizontalHeader();
    for (int c : {int(BusListModel::MachineNumber), int(BusListModel::Model),
                  int(BusListModel::State), int(BusListModel::Priority)}) {
        EXPECT_FALSE(busHeader->isSectionHidden(c));
        EXPECT_GE(busHeader->sectionViewportPosition(c), 0);
        EXPECT_LE(busHeader->sectionViewportPosition(c) + busHeader->sectionSize(c),
                  busHeader->viewport()->width())
            << "bus list column "
            << qPrintable(window->busPanel()->model()->headerData(c, Qt::Horizontal).toString());
    }

    inspectPages(1, QStringLiteral("DBU200 1"));
    inspectPages(150, QStringLiteral("DBU400 150"));
    inspectPages(7, QStringLiteral("DC controller 7"));
    // A 1280×800 laptop's window, its panel and title bar taken.
    window->setGeometry(QRect(screen.topLeft(), QSize(1280, 720)));
    settle();
    inspectPages(1, QStringLiteral("1280×720, DBU200 1"));
    inspectPages(7, QStringLiteral("1280×720, DC controller 7"));
    window->setGeometry(QRect(screen.topLeft(), QSize(1366, 768)));
    settle();

    // Each dock beside a drive's monitor, on its own, then all together.
    select({1});
    ASSERT_TRUE(
        waitFor([&] { return window->workspace()->drive() == window->drives()->parameters(1); }));
    window->workspace()->tabs()->setCurrentIndex(0);
    const QList<QDockWidget*> docks = window->findChildren<QDockWidget*>();
    ASSERT_GE(docks.size(), 3);
    for (QDockWidget* dock : docks) {
        dock->show();
        settle(300);
        inspect(window.get(), QStringLiteral("dock %1 open").arg(dock->windowTitle()));
        dock->hide();
    }
    window->monitorAll();
    window->findChild<QDockWidget*>(QStringLiteral("trafficDock"))->show();
    settle(300);
    inspect(window.get(), QStringLiteral("all docks open"));
    explainHeight();
    for (QDockWidget* dock : docks)
        dock->hide();
    settle();

    // The dialogs of the menus, as the menus open them.
    inspectModal(action(QStringLiteral("Connect")), QStringLiteral("connection dialog"));
    select({1, 2});
    settle();
    inspectModal(action(QStringLiteral("Write a setting to the selected drives")),
                 QStringLiteral("multi-drive write dialog"));
    action(QStringLiteral("Compare"))->trigger();
    settle();
    QDialog* compareDialog = nullptr;
    for (QDialog* d : window->findChildren<QDialog*>(QString(), Qt::FindDirectChildrenOnly)) {
        if (d->inherits("opentop::CompareDialog") && d->isVisible())
            compareDialog = d;
    }
    ASSERT_NE(compareDialog, nullptr);
    inspectDialog(compareDialog, QStringLiteral("compare dialog"));
    // Backup and restore open after a file is chosen: made as their actions make them, and
    // inspected with their work done (a backup of two drives, its restore preview, the file).
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("bus.json"));
    auto* backup = new BackupDialog(window->drives(), ConnectionSettings(), window.get());
    bool saved = false;
    QObject::connect(backup, &BackupDialog::backupFinished, [&](bool ok) { saved = ok; });
    backup->show();
    backup->startBackup({1, 7}, file);
    ASSERT_TRUE(waitFor([&] { return saved; }, 30000));
    inspectDialog(backup, QStringLiteral("backup dialog, two drives saved"));
    auto* restore = new RestoreDialog(window->drives(), window.get());
    restore->show();
    ASSERT_TRUE(restore->setPath(file));
    bool previewed = false;
    QObject::connect(restore, &RestoreDialog::previewFinished, [&] { previewed = true; });
    restore->preview();
    ASSERT_TRUE(waitFor([&] { return previewed; }, 30000));
    inspectDialog(restore, QStringLiteral("restore dialog, preview"));
    auto* viewer = new BackupViewer(window.get());
    ASSERT_TRUE(viewer->open(file));
    inspectDialog(viewer, QStringLiteral("backup viewer"));
    // End of line: the recipe editor with a recipe of the drives on the bus, the results browser.
    auto* editor = new RecipeEditor([this] { return window->drives(); }, window.get());
    editor->show();
    bool made = false;
    editor->newFromDrives({1, 7}, QStringLiteral("Layout"), QStringLiteral("A"),
                          [&](bool, const QString&) { made = true; });
    ASSERT_TRUE(waitFor([&] { return made; }, 30000));
    EXPECT_TRUE(editor->check().isEmpty());
    inspectDialog(editor, QStringLiteral("recipe editor, two drives"));
    inspectDialog(new ResultsBrowser(dir.filePath(QStringLiteral("none.db")), window.get()),
                  QStringLiteral("results browser"));
    // The Help menu.
    for (const QString& name : {QStringLiteral("User guide"), QStringLiteral("Keyboard shortcuts"),
                                QStringLiteral("About OpenTOP")}) {
        QAction* a = action(name);
        ASSERT_NE(a, nullptr);
        a->trigger();
        settle();
        QDialog* shown = nullptr;
        for (QDialog* d : window->findChildren<QDialog*>(QString(), Qt::FindDirectChildrenOnly)) {
            if (d->isVisible())
                shown = d;
        }
        ASSERT_NE(shown, nullptr) << qPrintable(name);
        inspectDialog(shown, name);
    }

    EXPECT_TRUE(problems.isEmpty()) << qPrintable(report());
}
