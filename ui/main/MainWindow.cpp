#include "main/MainWindow.h"

#include "ModbusClient.h"
#include "TrafficLog.h"
#include "alarms/AlarmBanner.h"
#include "alarms/AlarmExport.h"
#include "alarms/AlarmsPage.h"
#include "bus/BusDrives.h"
#include "bus/BusGroupTracker.h"
#include "bus/BusListModel.h"
#include "bus/BusOverview.h"
#include "bus/BusPanel.h"
#include "bus/BusRecallBar.h"
#include "bus/DriveStatusPoller.h"
#include "connection/ConnectionDialog.h"
#include "files/FileActions.h"
#include "groups/GroupsView.h"
#include "help/HelpActions.h"
#include "monitor/MonitorHub.h"
#include "monitor/MonitorPage.h"
#include "pages/DcControllerPage.h"
#include "profile/ProfileRegistry.h"
#include "run/ExitCheck.h"
#include "run/ExitGuard.h"
#include "run/StopAllButton.h"
#include "run/StopAllKeys.h"
#include "run/TestRunPanel.h"
#include "session/DeviceIdentifier.h"
#include "session/DeviceParameters.h"
#include "traffic/TrafficDescriber.h"
#include "traffic/TrafficLogView.h"
#include "trends/TrendPanel.h"
#include "widgets/StatusLight.h"
#include "workspace/DriveWorkspace.h"
#include "workspace/MultiDriveWriteDialog.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QGuiApplication>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QScreen>
#include <QScrollArea>
#include <QSettings>
#include <QSplitter>
#include <QStatusBar>
#include <QTabWidget>
#include <QTableView>
#include <QTimer>
#include <QToolBar>
#include <QVBoxLayout>
#include <algorithm>

namespace opentop {

MainWindow::MainWindow(ClientFactory factory, QWidget* parent)
    : QMainWindow(parent)
    , m_factory(std::move(factory))
    , m_log(std::make_unique<TrafficLog>())
    , m_workspace(new DriveWorkspace(this))
    , m_central(new QWidget(this))
    , m_splitter(new QSplitter(this))
    , m_connectionLabel(new QLabel(this))
    , m_linkLight(new StatusLight(this))
    , m_simBanner(new QLabel(this))
{
    setWindowTitle(tr("OpenTOP"));
    m_splitter->setObjectName(QStringLiteral("mainSplitter"));
    m_splitter->addWidget(new QWidget(m_splitter)); // the bus panel, once connected
    m_splitter->addWidget(m_workspace);
    m_splitter->setStretchFactor(1, 1);
    auto* column = new QVBoxLayout(m_central);
    column->setContentsMargins(0, 0, 0, 0);
    // A simulated bus is unmistakable: a permanent coloured marker in the status bar (and the
    // window title) say so; it costs no height on a laptop screen.
    m_simBanner->setObjectName(QStringLiteral("simulatedBanner"));
    m_simBanner->setText(tr("SIMULATED BUS — no hardware"));
    m_simBanner->setToolTip(tr("These drives exist only in this program; nothing moves."));
    m_simBanner->setStyleSheet(QStringLiteral("background: #f9a825; color: black; "
                                              "font-weight: bold; padding: 0 8px;"));
    m_simBanner->hide();
    column->addWidget(m_splitter, 1); // the alarm banner goes above it once connected
    setCentralWidget(m_central);
    // Every frame, decoded with parameter names, in a dock that can be shown or hidden.
    auto* trafficDock = new QDockWidget(tr("Traffic log"), this);
    trafficDock->setObjectName(QStringLiteral("trafficDock"));
    trafficDock->setWidget(new TrafficLogView(m_log.get(), trafficDock));
    addDockWidget(Qt::BottomDockWidgetArea, trafficDock);
    trafficDock->hide();
    // Live views of the whole bus; their contents are made per connection.
    for (const auto& [name, title] :
         {std::pair(QStringLiteral("overviewDock"), tr("Bus overview")),
          std::pair(QStringLiteral("trendDock"), tr("Trends")),
          std::pair(QStringLiteral("groupsDock"), tr("Communication groups"))}) {
        auto* d = new QDockWidget(title, this);
        d->setObjectName(name);
        d->setWidget(new QLabel(tr("Not connected"), d));
        addDockWidget(Qt::BottomDockWidgetArea, d);
        d->hide();
    }
    // The bottom docks share one place as tabs: side by side they would not fit a laptop's
    // width, and each still has the full width for its columns.
    tabifyDockWidget(trafficDock, dock(QStringLiteral("overviewDock")));
    tabifyDockWidget(trafficDock, dock(QStringLiteral("trendDock")));
    tabifyDockWidget(trafficDock, dock(QStringLiteral("groupsDock")));
    m_linkLight->setObjectName(QStringLiteral("linkLight"));
    m_linkLight->setLed(DriveStatus::Led::Grey, tr("Not connected"));
    statusBar()->addPermanentWidget(m_simBanner);
    statusBar()->addPermanentWidget(m_linkLight);
    statusBar()->addPermanentWidget(m_connectionLabel);
    buildActions();
    // STOP ALL's keys work everywhere in the program, modal dialogs included; the button itself
    // is made per connection.
    new StopAllKeys([this] { return m_stopAll; }, this);
    QSettings settings;
    fitToScreen(
        restoreGeometry(settings.value(QStringLiteral("mainWindow/geometry")).toByteArray()));
    restoreState(settings.value(QStringLiteral("mainWindow/state")).toByteArray());
    m_splitterState = settings.value(QStringLiteral("mainWindow/splitter")).toByteArray();
}

MainWindow::~MainWindow()
{
    teardown();
}

void MainWindow::fitToScreen(bool remembered)
{
    // Laptop first: never larger than the screen's available area (a 1366×768 screen has about
    // 730 px for a window once its panel and the title bar are taken), and a remembered geometry
    // from a larger screen is brought back onto this one.
    const QRect available =
        (screen() ? screen() : QGuiApplication::primaryScreen())->availableGeometry();
    const QSize frame(8, 32); // the window manager's frame and title bar, before it tells
    const QSize room = available.size() - frame;
    QSize size = remembered ? this->size() : QSize(1280, 800);
    size = size.boundedTo(room);
    resize(size);
    QPoint at = remembered ? pos() : available.topLeft();
    at.setX(std::max(available.left(),
                     std::min(at.x(), available.right() + 1 - size.width() - frame.width())));
    at.setY(std::max(available.top(),
                     std::min(at.y(), available.bottom() + 1 - size.height() - frame.height())));
    move(at);
}

void MainWindow::buildActions()
{
    QMenu* file = menuBar()->addMenu(tr("&Bus"));
    QToolBar* toolbar = addToolBar(tr("Main"));
    toolbar->setObjectName(QStringLiteral("mainToolbar"));
    m_toolbar = toolbar;
    QAction* connectAction = file->addAction(tr("&Connect…"), this, &MainWindow::chooseConnection);
    connectAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_K));
    connectAction->setToolTip(tr("Choose the serial port, gateway or simulated bus (Ctrl+K)"));
    toolbar->addAction(connectAction);
    QAction* scan = file->addAction(tr("&Scan bus"), this, [this] {
        if (m_panel && !m_panel->isScanning())
            m_panel->startScan(1, 247);
    });
    scan->setShortcut(QKeySequence(Qt::Key_F5));
    toolbar->addAction(scan);
    m_disconnect = file->addAction(tr("&Disconnect"), this, &MainWindow::disconnectBus);
    m_disconnect->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_K));
    m_disconnect->setEnabled(false);
    connect(this, &MainWindow::connectionChanged, m_disconnect, &QAction::setEnabled);
    file->addAction(tr("Communication &groups…"), this, [this] {
        dock(QStringLiteral("groupsDock"))->show();
        dock(QStringLiteral("groupsDock"))->raise();
    });
    file->addAction(tr("&Export alarm histories…"), this, &MainWindow::exportAlarms);
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);

    // Backup, restore, compare and the file viewer (they take the bus as it is when used).
    new FileActions(
        this, menuBar()->addMenu(tr("&Files")), [this] { return m_drives; },
        [this] { return m_selected; }, [this] { return m_settings; }, this);

    QMenu* drive = menuBar()->addMenu(tr("&Drive"));
    QAction* writeAll =
        drive->addAction(tr("&Write all pending"), m_workspace, &DriveWorkspace::writeAll);
    writeAll->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_W));
    QAction* reread =
        drive->addAction(tr("&Re-read all"), m_workspace, &DriveWorkspace::refreshAll);
    reread->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
    m_multiWrite = drive->addAction(tr("Write a setting to the selected drives…"), this,
                                    &MainWindow::writeToSelected);
    m_multiWrite->setEnabled(false);
    toolbar->addAction(writeAll);
    toolbar->addAction(m_multiWrite);
    toolbar->addSeparator();
    QMenu* view = menuBar()->addMenu(tr("&View"));
    // The docks' own actions keep the menu's check marks in step with a dock closed by its
    // title bar button.
    const std::tuple<QString, QString, QKeySequence> docks[] = {
        {QStringLiteral("trafficDock"), tr("&Traffic log"), QKeySequence(Qt::CTRL | Qt::Key_T)},
        {QStringLiteral("overviewDock"), tr("Bus &overview"),
         QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_O)},
        {QStringLiteral("trendDock"), tr("T&rends"), QKeySequence(Qt::CTRL | Qt::Key_G)},
        {QStringLiteral("groupsDock"), tr("Communication &groups"),
         QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_G)}};
    for (const auto& [name, text, key] : docks) {
        QAction* a = dock(name)->toggleViewAction();
        a->setText(text);
        a->setShortcut(key);
        view->addAction(a);
    }
    new HelpActions(this, menuBar()->addMenu(tr("&Help")));
}

void MainWindow::teardown()
{
    // The pages watch drives through the hub and use their sessions: gone before them.
    while (m_workspace->tabs()->count() > 0)
        delete m_workspace->tabs()->widget(0);
    m_workspace->setDrive(nullptr, QString());
    delete m_recall; // before the drives: it remembers what is left of them
    m_recall = nullptr;
    for (const QString& name : {QStringLiteral("overviewDock"), QStringLiteral("trendDock"),
                                QStringLiteral("groupsDock")}) {
        QWidget* old = dock(name)->widget();
        dock(name)->setWidget(new QLabel(tr("Not connected"), dock(name)));
        delete old;
    }
    m_overview = nullptr;
    m_trends = nullptr;
    m_groupsView = nullptr;
    delete m_hub; // before the drives: its monitors use their sessions
    m_hub = nullptr;
    if (m_stopAllAction) {
        m_toolbar->removeAction(m_stopAllAction);
        m_stopAllAction = nullptr;
    }
    delete m_stopAll;
    m_stopAll = nullptr;
    if (m_exitGuard) {
        m_exitGuard->deleteLater(); // its answer may be what brought us here
        m_exitGuard = nullptr;
    }
    delete m_banner;
    m_banner = nullptr;
    m_log->setDescriber({});
    delete m_panel;
    m_panel = nullptr;
    delete m_poller;
    m_poller = nullptr;
    delete m_drives;
    m_drives = nullptr;
    m_groups = nullptr; // the drives' child
    m_client.reset();   // bounded shutdown of the bus worker
    m_simBanner->hide();
    m_connected = false;
    m_linkLight->setLed(DriveStatus::Led::Grey, tr("Not connected"));
    // A start confirmed for this bus says nothing about the next one (another machine may use
    // the same machine numbers).
    TestRunPanel::forgetConfirmations();
}

void MainWindow::connectTo(const ConnectionSettings& settings,
                           const QHash<int, QString>& knownTypes)
{
    // A start confirmed for this bus says nothing about the next one.
    TestRunPanel::forgetConfirmations();
    dropCandidate();
    QString error;
    std::unique_ptr<ModbusClient> client = m_factory(settings, m_log.get(), &error);
    if (!client) {
        refuseConnection(settings, error);
        return;
    }
    // A working connection stays until the new one is open: a mistyped port or a gateway that
    // does not answer must not cost the bus one was working on. Reopening the same serial port
    // (other settings) cannot wait: the port is ours until it is closed.
    const bool samePort = m_connected && settings.kind == ConnectionSettings::Kind::Serial &&
                          m_settings.kind == ConnectionSettings::Kind::Serial &&
                          settings.port == m_settings.port;
    if (m_connected && !samePort) {
        m_candidate = std::move(client);
        m_candidateSettings = settings;
        m_candidateTypes = knownTypes;
        setConnectionText(tr("Connecting to %1… (still connected to %2)")
                              .arg(m_candidate->describe(), m_client->describe()),
                          false);
        connect(m_candidate.get(), &ModbusClient::opened, this,
                [this](bool ok, const QString& why) {
                    if (!ok) {
                        const ConnectionSettings failed = m_candidateSettings;
                        dropCandidate();
                        refuseConnection(failed, why);
                        return;
                    }
                    std::unique_ptr<ModbusClient> opened = std::move(m_candidate);
                    disconnect(opened.get(), &ModbusClient::opened, this, nullptr);
                    adopt(std::move(opened), m_candidateSettings, m_candidateTypes);
                    onOpened(true, QString());
                });
        m_candidate->open();
        return;
    }
    adopt(std::move(client), settings, knownTypes);
    connect(m_client.get(), &ModbusClient::opened, this, &MainWindow::onOpened);
    m_client->open();
}

void MainWindow::dropCandidate()
{
    if (!m_candidate)
        return;
    disconnect(m_candidate.get(), nullptr, this, nullptr);
    // Possibly inside its own signal: deleted once that has returned.
    m_candidate.release()->deleteLater();
}

void MainWindow::refuseConnection(const ConnectionSettings& settings, const QString& error)
{
    const QString why = ConnectionDialog::explainOpenError(settings, error);
    if (m_connected && m_client) {
        // The bus one was working on stays as it was.
        setConnectionText(
            tr("Connected: %1 (the new connection failed: %2)").arg(m_client->describe(), error),
            true);
        QMessageBox::warning(
            this, tr("Cannot connect"),
            tr("%1\n\nStill connected to %2; nothing was changed.").arg(why, m_client->describe()));
        return;
    }
    setConnectionText(tr("Not connected: %1").arg(error), true);
    QMessageBox::warning(this, tr("Cannot connect"), why);
    emit connectionChanged(false);
}

void MainWindow::adopt(std::unique_ptr<ModbusClient> client, const ConnectionSettings& settings,
                       const QHash<int, QString>& knownTypes)
{
    teardown();
    m_settings = settings;
    m_knownTypes = knownTypes;
    m_client = std::move(client);
    m_drives = new BusDrives(m_client.get(), ProfileRegistry::builtIn(), this);
    m_poller = new DriveStatusPoller(m_drives, this);
    m_groups = new BusGroupTracker(m_drives);
    m_panel = new BusPanel(m_drives, m_poller, m_splitter);
    m_hub = new MonitorHub(m_drives, this);
    buildMonitorDocks();
    // The traffic log names parameters and who else a write reaches (group children).
    TrafficDescriber describer(m_drives, ProfileRegistry::builtIn());
    m_log->setDescriber(describer.describer());
    connect(m_groups, &BusGroupTracker::groupsChanged, m_groups,
            [describer, groups = m_groups]() mutable { describer.setGroups(groups->groups()); });
    // STOP ALL is always on the toolbar and on the keyboard (StopAllButton::shortcuts()).
    m_stopAll = new StopAllButton(m_drives, m_toolbar);
    m_stopAllAction = m_toolbar->addWidget(m_stopAll);
    // No way out of this bus (quit, another connection) leaves a motor running unannounced.
    m_exitGuard = new ExitGuard(m_drives, m_poller, this);
    m_banner = new AlarmBanner(m_poller, m_central);
    static_cast<QVBoxLayout*>(m_central->layout())->insertWidget(0, m_banner);
    // The drives last seen here, offered back (not when the caller names the drives).
    m_recall = new BusRecallBar(m_drives, settings, knownTypes.isEmpty(), m_central);
    auto* column = static_cast<QVBoxLayout*>(m_central->layout());
    column->insertWidget(column->indexOf(m_splitter), m_recall);
    connect(m_recall, &BusRecallBar::restoreRequested, this,
            [this](const QHash<int, QString>& types) {
                m_knownTypes = types;
                if (m_connected)
                    identifyKnown();
            });
    connect(m_recall, &BusRecallBar::scanRequested, this, [this] {
        if (m_panel && m_connected && !m_panel->isScanning())
            m_panel->startScan(1, 247);
    });
    // The header names the model once the variant is known (identified or set by hand).
    connect(m_drives, &BusDrives::driveChanged, this, [this](int slave) {
        if (m_workspace->drive() && m_workspace->drive() == m_drives->parameters(slave))
            m_workspace->setTitle(driveTitle(slave));
    });
    // A group setup that is wrong is said where the engineer looks, not only in its view.
    connect(m_groups, &BusGroupTracker::groupsChanged, this, [this] {
        const QVector<BusGroups::Problem> problems = m_groups->groups().problems();
        if (!problems.isEmpty())
            statusBar()->showMessage(tr("Communication groups: %1 (Bus › Communication groups)")
                                         .arg(BusGroups::describe(problems.first())),
                                     15000);
    });
    const bool simulated = settings.kind == ConnectionSettings::Kind::Simulated;
    m_simBanner->setVisible(simulated);
    connect(m_banner, &AlarmBanner::showAlarms, this, &MainWindow::showAlarmsOf);
    // STOP ALL may end in alarms (or clear a run that hid one): the open page reads again.
    connect(m_stopAll, &StopAllButton::finished, this, [this] {
        if (AlarmsPage* page = alarmsPage())
            page->refresh();
    });
    // The placeholder of the first connection; on a reconnection the old panel is gone and
    // the first widget is the workspace, which stays.
    if (m_splitter->widget(0) != m_workspace)
        delete m_splitter->widget(0);
    m_splitter->insertWidget(0, m_panel);
    m_splitter->setStretchFactor(0, 0);
    // The remembered division, or one where the bus list shows its first columns up to the
    // control priority (the rest scroll) and the drive's pages keep the most of a laptop's width.
    if (!m_splitter->restoreState(m_splitterState)) {
        const QHeaderView* header = m_panel->view()->horizontalHeader();
        const int priorityEnd = header->sectionPosition(BusListModel::Priority) +
                                header->sectionSize(BusListModel::Priority);
        const int list = std::clamp(priorityEnd + 40, 360, std::max(360, width() * 2 / 5));
        m_splitter->setSizes({list, std::max(600, width() - list)});
    }
    connect(m_panel, &BusPanel::selectionChanged, this, &MainWindow::showDrive);
    connect(m_client.get(), &ModbusClient::connectionLost, this, [this](const QString& lost) {
        m_connected = false; // nothing to keep when another connection is tried
        setConnectionText(tr("Connection lost: %1").arg(lost), true);
        // Every live view greys at once, before the message is read.
        setLinkUp(false, tr("Connection lost: %1").arg(lost));
        auto* box = new QMessageBox(QMessageBox::Warning, tr("Connection lost"),
                                    ConnectionDialog::explainOpenError(m_settings, lost),
                                    QMessageBox::Ok, this);
        box->setObjectName(QStringLiteral("connectionLostBox"));
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
    });
    setWindowTitle(simulated
                       ? tr("OpenTOP — SIMULATED BUS (no hardware) — %1").arg(m_client->describe())
                       : tr("OpenTOP — %1").arg(m_client->describe()));
    setConnectionText(tr("Connecting to %1…").arg(m_client->describe()), false);
}

void MainWindow::setConnectionText(const QString& text, bool problem)
{
    // A port error can be several long lines: the status bar shows the first, shortened, so
    // that it never widens the window; the whole text is in the tooltip.
    const QString first = text.section(QLatin1Char('\n'), 0, 0);
    m_connectionLabel->setText(
        m_connectionLabel->fontMetrics().elidedText(first, Qt::ElideRight, 520));
    m_connectionLabel->setToolTip(text);
    m_connectionLabel->setStyleSheet(problem ? QStringLiteral("color: white; background: #b01c1c; "
                                                              "font-weight: bold; padding: 0 6px;")
                                             : QString());
}

void MainWindow::setLinkUp(bool up, const QString& why)
{
    m_connected = up;
    if (m_drives)
        m_drives->setLinkUp(up);
    m_linkLight->setLed(up ? DriveStatus::Led::Green : DriveStatus::Led::Grey, why);
}

AlarmsPage* MainWindow::alarmsPage() const
{
    for (int i = 0; i < m_workspace->tabs()->count(); ++i) {
        if (auto* page = qobject_cast<AlarmsPage*>(m_workspace->tabs()->widget(i)))
            return page;
    }
    return nullptr;
}

void MainWindow::showAlarmsOf(int slave)
{
    if (!m_panel || !m_drives || !m_drives->contains(slave))
        return;
    const int row = m_panel->model()->rowOf(slave);
    if (m_panel->selectedSlaves() != QVector<int>{slave}) {
        // This drive alone (a row added to a selection of several would open the first's).
        const QModelIndex index = m_panel->model()->index(row, 0);
        m_panel->view()->selectionModel()->setCurrentIndex(
            index, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    }
    // The pages follow the selection at once; make sure they are this drive's.
    showDrive({slave});
    if (AlarmsPage* page = alarmsPage()) {
        m_workspace->tabs()->setCurrentWidget(page);
        page->refresh();
    }
}

void MainWindow::onOpened(bool ok, const QString& error)
{
    setLinkUp(ok, ok ? tr("Connected: %1").arg(m_client->describe())
                     : tr("Not connected: %1").arg(error));
    if (!ok) {
        refuseConnection(m_settings, error);
        return;
    }
    setConnectionText(m_settings.kind == ConnectionSettings::Kind::Simulated
                          ? tr("Connected: %1 (simulated, no hardware)").arg(m_client->describe())
                          : tr("Connected: %1").arg(m_client->describe()),
                      false);
    m_poller->start();
    identifyKnown();
    emit connectionChanged(true);
}

void MainWindow::identifyKnown()
{
    auto* identifier = new DeviceIdentifier(m_client.get(), ProfileRegistry::builtIn(), m_drives);
    for (auto it = m_knownTypes.cbegin(); it != m_knownTypes.cend(); ++it) {
        const int slave = it.key();
        const QString type = it.value();
        identifier->identify(slave, [this, type](DeviceInfo info) {
            QString variant;
            const Profile* p = ProfileRegistry::builtIn().forDeviceType(type, &variant);
            if (info.state == DeviceInfo::State::Present && info.variant.isEmpty() && p &&
                p->family == info.family && p->variant(variant)) {
                info.variant = variant;
                info.model = p->variant(variant)->model;
                info.detail = tr("The drive does not report its variant; %1 is the configured one.")
                                  .arg(info.model);
            }
            m_drives->update(info);
        });
    }
}

void MainWindow::showDrive(const QVector<int>& slaves)
{
    m_selected = slaves;
    // Several drives of one family: one setting can be written to all of them.
    bool sameFamily = slaves.size() > 1;
    for (int s : slaves)
        sameFamily = sameFamily && m_drives->parameters(s) &&
                     m_drives->info(s).family == m_drives->info(slaves.first()).family;
    m_multiWrite->setEnabled(sameFamily);
    if (slaves.isEmpty() || !m_drives->parameters(slaves.first())) {
        m_workspace->setDrive(nullptr, QString());
        return;
    }
    const DeviceInfo info = m_drives->info(slaves.first());
    if (m_workspace->drive() == m_drives->parameters(info.slave))
        return;
    m_workspace->setDrive(m_drives->parameters(info.slave), driveTitle(info.slave));
    // The monitoring side of the drive: live values, test run and alarm histories.
    auto* monitor = new MonitorPage(m_hub, m_drives->parameters(info.slave), m_workspace->tabs());
    // First: what a drive is doing is what one wants to see on selecting it (as on a TOP-1).
    m_workspace->tabs()->insertTab(0, monitor, tr("Monitor"));
    m_workspace->tabs()->setCurrentIndex(0);
    // The DC controller's settings page shows what the controller does now, too.
    for (DcControllerPage* page : m_workspace->findChildren<DcControllerPage*>())
        page->setMonitorHub(m_hub);
    auto* run = new TestRunPanel(m_drives, info.slave, m_workspace->tabs());
    run->setMonitorHub(m_hub); // live state; the drive is polled (and trended) while shown
    run->setPollingActive(m_poller->isActive());
    // Scrolls rather than raising the window's minimum height above a laptop's screen.
    auto* runScroll = new QScrollArea(m_workspace->tabs());
    runScroll->setFrameShape(QFrame::NoFrame);
    runScroll->setWidgetResizable(true);
    runScroll->setWidget(run);
    m_workspace->tabs()->addTab(runScroll, tr("Test run"));
    auto* alarms = new AlarmsPage(m_drives->session(info.slave), m_workspace->tabs());
    m_workspace->tabs()->addTab(alarms, tr("Alarms"));
    // Live: raised, cleared and power-cycled alarms show without a click, as on the banner.
    alarms->followLive(m_hub, m_poller);
    alarms->refresh();
}

QString MainWindow::driveTitle(int slave) const
{
    const DeviceInfo info = m_drives->info(slave);
    return tr("Machine number %1 (%2, %3) — %4, firmware V%5")
        .arg(info.slave)
        .arg(DeviceInfo::hexText(info.slave), DeviceInfo::switchText(info.slave), info.model,
             info.firmware);
}

void MainWindow::buildMonitorDocks()
{
    m_overview = new BusOverview(m_drives, m_hub, dock(QStringLiteral("overviewDock")));
    connect(m_overview, &BusOverview::driveActivated, this,
            [this](int slave) { m_panel->view()->selectRow(m_panel->model()->rowOf(slave)); });
    m_trends = new TrendPanel(m_hub, dock(QStringLiteral("trendDock")));
    m_groupsView = new GroupsView(m_groups, dock(QStringLiteral("groupsDock")));
    for (const auto& [name, widget] :
         {std::pair(QStringLiteral("overviewDock"), (QWidget*)m_overview),
          std::pair(QStringLiteral("trendDock"), (QWidget*)m_trends),
          std::pair(QStringLiteral("groupsDock"), (QWidget*)m_groupsView)}) {
        QWidget* old = dock(name)->widget();
        dock(name)->setWidget(widget);
        delete old;
    }
}

QDockWidget* MainWindow::dock(const QString& name) const
{
    return findChild<QDockWidget*>(name);
}

void MainWindow::monitorAll()
{
    if (!m_drives)
        return;
    dock(QStringLiteral("overviewDock"))->show();
    dock(QStringLiteral("trendDock"))->show();
    m_trends->showDrives(m_drives->slaves());
}

void MainWindow::writeToSelected()
{
    if (m_selected.size() < 2)
        return;
    MultiDriveWriteDialog dialog(m_drives, m_selected, QString(), this);
    dialog.exec();
}

void MainWindow::exportAlarms()
{
    if (!m_drives || m_drives->slaves().isEmpty())
        return;
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export alarm histories"), QStringLiteral("alarms.csv"), tr("CSV files (*.csv)"));
    if (path.isEmpty())
        return;
    auto* exporter = new AlarmExport(m_drives, this);
    connect(exporter, &AlarmExport::finished, this, [this, exporter](bool, const QString& message) {
        statusBar()->showMessage(message, 10000);
        exporter->deleteLater();
    });
    exporter->exportTo(path);
}

void MainWindow::chooseConnection()
{
    ConnectionDialog dialog(this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    const ConnectionSettings settings = dialog.settings();
    if (!m_exitGuard) {
        connectTo(settings);
        return;
    }
    m_exitGuard->check(tr("connect elsewhere"), [this, settings] { connectTo(settings); });
}

void MainWindow::disconnectBus()
{
    if (!m_drives)
        return;
    // As on quitting: running drives and drives left in communication priority are named first.
    const auto close = [this] {
        teardown();
        setConnectionText(tr("Not connected (disconnected)"), false);
        emit connectionChanged(false);
    };
    if (m_exitGuard)
        m_exitGuard->check(tr("disconnect"), close);
    else
        close();
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    int pending = 0;
    if (m_drives) {
        for (int s : m_drives->slaves())
            pending += m_drives->parameters(s) ? m_drives->parameters(s)->pendingNames().size() : 0;
    }
    if (pending > 0 &&
        QMessageBox::question(
            this, tr("Unwritten changes"),
            tr("%n edit(s) have not been written to the drives. Quit and discard them?", nullptr,
               pending),
            QMessageBox::Discard | QMessageBox::Cancel,
            QMessageBox::Cancel) != QMessageBox::Discard) {
        event->ignore();
        return;
    }
    // Drives running or left in communication priority: ask first (outside this event).
    if (!m_leavingChecked && m_exitGuard && m_drives && m_poller &&
        !ExitCheck::collect(*m_drives, *m_poller).isEmpty()) {
        event->ignore();
        QTimer::singleShot(0, this, [this] {
            if (m_exitGuard) {
                m_exitGuard->check(tr("quit"), [this] {
                    m_leavingChecked = true;
                    close();
                });
            }
        });
        return;
    }
    QSettings settings;
    settings.setValue(QStringLiteral("mainWindow/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("mainWindow/state"), saveState());
    m_splitterState = m_splitter->saveState();
    settings.setValue(QStringLiteral("mainWindow/splitter"), m_splitterState);
    event->accept();
}

} // namespace opentop
