#include "ui/main/MainMenus.h"

#include "model/bus/BusDrives.h"
#include "model/i18n/Language.h"
#include "ui/alarms/AlarmExport.h"
#include "ui/bus/BusPanel.h"
#include "ui/connection/ConnectionDialog.h"
#include "ui/files/FileActions.h"
#include "ui/help/HelpActions.h"
#include "ui/i18n/LanguageMenu.h"
#include "ui/main/BusDocks.h"
#include "ui/main/MainWindow.h"
#include "ui/main/Reconnection.h"
#include "ui/workspace/DriveWorkspace.h"
#include "ui/workspace/MultiDriveWriteDialog.h"

#include <QAction>
#include <QDockWidget>
#include <QFileDialog>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>
#include <QToolBar>

namespace opentop {

MainMenus::MainMenus(MainWindow* window, BusDocks* docks, std::function<QVector<int>()> selected,
                     std::function<ConnectionSettings()> settings)
    : QObject(window)
    , m_window(window)
    , m_docks(docks)
    , m_selected(std::move(selected))
{
    QMenuBar* bar = window->menuBar();
    QMenu* file = bar->addMenu(tr("&Bus"));
    QToolBar* toolbar = window->addToolBar(tr("Main"));
    toolbar->setObjectName(QStringLiteral("mainToolbar"));
    m_toolbar = toolbar;
    QAction* connectAction = file->addAction(tr("&Connect…"), this, &MainMenus::chooseConnection);
    connectAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_K));
    connectAction->setToolTip(tr("Choose the serial port, gateway or simulated bus (Ctrl+K)"));
    toolbar->addAction(connectAction);
    // The last connection again, after its link dropped or a disconnect (Ctrl+R).
    file->addAction(window->reconnection()->action());
    QAction* scan = file->addAction(tr("&Scan bus"), window, [window] {
        if (BusPanel* panel = window->busPanel(); panel && !panel->isScanning())
            panel->startScan(1, 247);
    });
    scan->setShortcut(QKeySequence(Qt::Key_F5));
    toolbar->addAction(scan);
    m_disconnect = file->addAction(tr("&Disconnect"), window, &MainWindow::disconnectBus);
    m_disconnect->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_K));
    m_disconnect->setEnabled(false);
    connect(window, &MainWindow::connectionChanged, m_disconnect, &QAction::setEnabled);
    // The groups are the bus's: their key is listed here, where the command is (View only
    // toggles the dock).
    QAction* groups = file->addAction(tr("Communication &groups…"), window, [docks] {
        docks->dock(QStringLiteral("groupsDock"))->show();
        docks->dock(QStringLiteral("groupsDock"))->raise();
    });
    groups->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_G));
    file->addAction(tr("&Export alarm histories…"), this, &MainMenus::exportAlarms);
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, window, &QWidget::close);

    // Backup, restore, compare and the file viewer (they take the bus as it is when used).
    QMenu* files = bar->addMenu(tr("&Files"));
    new FileActions(
        window, files, [window] { return window->drives(); }, m_selected, std::move(settings),
        window);

    QMenu* drive = bar->addMenu(tr("&Drive"));
    DriveWorkspace* workspace = window->workspace();
    QAction* writeAll =
        drive->addAction(tr("&Write all pending"), workspace, &DriveWorkspace::writeAll);
    writeAll->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_W));
    QAction* reread = drive->addAction(tr("&Re-read all"), workspace, &DriveWorkspace::refreshAll);
    reread->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
    m_multiWrite = drive->addAction(tr("Write a setting to the selected drives…"), this,
                                    &MainMenus::writeToSelected);
    m_multiWrite->setEnabled(false);
    // The selected drive's pages from the keyboard, as tabs elsewhere (the side tabs take no
    // focus while a value is being typed).
    drive->addSeparator();
    QAction* nextPage = drive->addAction(tr("&Next page"), workspace, [workspace] {
        QTabWidget* tabs = workspace->tabs();
        if (tabs->count() > 0)
            tabs->setCurrentIndex((tabs->currentIndex() + 1) % tabs->count());
    });
    nextPage->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_PageDown));
    QAction* previousPage = drive->addAction(tr("&Previous page"), workspace, [workspace] {
        QTabWidget* tabs = workspace->tabs();
        if (tabs->count() > 0)
            tabs->setCurrentIndex((tabs->currentIndex() + tabs->count() - 1) % tabs->count());
    });
    previousPage->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_PageUp));
    toolbar->addAction(writeAll);
    toolbar->addAction(m_multiWrite);
    toolbar->addSeparator();
    // Scanning, writing and reading need a bus whose link is up; without one they would only
    // fail (and Ctrl+R is Reconnect while the link is down).
    for (QAction* needsBus : {scan, writeAll, reread}) {
        needsBus->setEnabled(window->isConnected());
        connect(window, &MainWindow::connectionChanged, needsBus, &QAction::setEnabled);
        connect(window, &MainWindow::linkChanged, needsBus, &QAction::setEnabled);
    }
    QMenu* view = bar->addMenu(tr("&View"));
    m_view = view;
    m_editing = {files, drive};
    // The docks' own actions keep the menu's check marks in step with a dock closed by its
    // title bar button.
    const std::tuple<QString, QString, QKeySequence> docksActions[] = {
        {QStringLiteral("trafficDock"), tr("&Traffic log"), QKeySequence(Qt::CTRL | Qt::Key_T)},
        {QStringLiteral("overviewDock"), tr("Bus &overview"),
         QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_O)},
        {QStringLiteral("trendDock"), tr("T&rends"), QKeySequence(Qt::CTRL | Qt::Key_G)},
        {QStringLiteral("groupsDock"), tr("Communication &groups"), QKeySequence()}};
    for (const auto& [name, text, key] : docksActions) {
        QAction* a = docks->dock(name)->toggleViewAction();
        a->setText(text);
        a->setShortcut(key);
        view->addAction(a);
    }
    view->addSeparator();
    auto* language = new LanguageMenu(window);
    view->addMenu(language);
    connect(language, &LanguageMenu::restartNeeded, window, [window](const QString& code) {
        // Asynchronous: nothing waits on it, and a running drive's controls stay reachable.
        auto* box = new QMessageBox(
            QMessageBox::Information, tr("Language"),
            tr("OpenTOP will be in %1 the next time it starts.").arg(Language::nativeName(code)),
            QMessageBox::Ok, window);
        box->setObjectName(QStringLiteral("languageRestartBox"));
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
    });
    m_eol = bar->addMenu(tr("&End of line"));
    m_editing << m_eol;
    new HelpActions(window, bar->addMenu(tr("&Help")));
}

void MainMenus::chooseConnection()
{
    ConnectionDialog dialog(m_window);
    Reconnection* reconnection = m_window->reconnection();
    if (reconnection->hasLast()) // the window's last connection, however it was made
        dialog.setSettings(reconnection->last());
    if (dialog.exec() != QDialog::Accepted)
        return;
    const ConnectionSettings settings = dialog.settings();
    // The same port, gateway or simulated bus while not connected: coming back, with its
    // drives and page, and nothing to ask (nothing could be sent to the drives meanwhile).
    if (!m_window->isConnected() && reconnection->reconnectWith(settings))
        return;
    m_window->checkLeaving(tr("connect elsewhere"),
                           [window = m_window, settings] { window->connectTo(settings); });
}

void MainMenus::exportAlarms()
{
    BusDrives* drives = m_window->drives();
    if (!drives || drives->slaves().isEmpty())
        return;
    const QString path =
        QFileDialog::getSaveFileName(m_window, tr("Export alarm histories"),
                                     QStringLiteral("alarms.csv"), tr("CSV files (*.csv)"));
    if (path.isEmpty())
        return;
    auto* exporter = new AlarmExport(drives, m_window);
    connect(exporter, &AlarmExport::finished, m_window,
            [window = m_window, exporter](bool, const QString& message) {
                window->statusBar()->showMessage(message, 10000);
                exporter->deleteLater();
            });
    exporter->exportTo(path);
}

void MainMenus::writeToSelected()
{
    const QVector<int> selected = m_selected();
    if (selected.size() < 2)
        return;
    MultiDriveWriteDialog dialog(m_window->drives(), selected, QString(), m_window);
    dialog.exec();
}

} // namespace opentop
