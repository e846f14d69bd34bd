#include "ui/main/MainWindow.h"

#include "model/bus/BusDrives.h"
#include "model/bus/BusGroupTracker.h"
#include "model/bus/DriveStatusPoller.h"
#include "model/bus/FixedLineHint.h"
#include "model/monitor/MonitorHub.h"
#include "model/profile/ProfileRegistry.h"
#include "model/session/DeviceIdentifier.h"
#include "model/session/DeviceParameters.h"
#include "model/station/EolStation.h"
#include "model/traffic/TrafficDescriber.h"
#include "transport/ModbusClient.h"
#include "transport/TrafficLog.h"
#include "ui/alarms/AlarmBanner.h"
#include "ui/alarms/AlarmsPage.h"
#include "ui/bus/BusPanel.h"
#include "ui/bus/BusRecallBar.h"
#include "ui/connection/ConnectionDialog.h"
#include "ui/eol/EolMenu.h"
#include "ui/eol/ProductionMode.h"
#include "ui/main/LinkBar.h"
#include "ui/main/MainMenus.h"
#include "ui/main/Reconnection.h"
#include "ui/run/ExitGuard.h"
#include "ui/run/StopAllButton.h"
#include "ui/run/StopAllKeys.h"
#include "ui/run/TestRunPanel.h"
#include "ui/workspace/DriveWorkspace.h"
#include "ui/workspace/ParameterInitBox.h"

#include <QAction>
#include <QCloseEvent>
#include <QMenu>
#include <QMessageBox>
#include <QSplitter>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>
#include <QVBoxLayout>

namespace opentop {

MainWindow::MainWindow(ClientFactory factory, QWidget* parent)
    : QMainWindow(parent)
    , m_factory(std::move(factory))
    , m_log(std::make_unique<TrafficLog>())
    , m_workspace(new DriveWorkspace(this))
    , m_central(new QWidget(this))
    , m_splitter(new QSplitter(this))
    , m_status(new ConnectionStatus(this))
    , m_geometry(this, m_splitter)
    , m_reconnection(new Reconnection(this))
{
    setWindowTitle(tr("OpenTOP"));
    m_splitter->setObjectName(QStringLiteral("mainSplitter"));
    m_splitter->addWidget(new QWidget(m_splitter)); // the bus panel, once connected
    m_splitter->addWidget(m_workspace);
    m_splitter->setStretchFactor(1, 1);
    auto* column = new QVBoxLayout(m_central);
    column->setContentsMargins(0, 0, 0, 0);
    column->addWidget(m_reconnection->bar()); // hidden until the link drops
    column->addWidget(m_splitter, 1);         // the alarm banner goes above them once connected
    setCentralWidget(m_central);
    m_docks = new BusDocks(this, m_log.get());
    m_status->showIn(statusBar());
    // After a parameter initialisation the drive answers at its factory line settings: the
    // box offers to reconnect at them, and this window does it (queued: the reconnect replaces
    // the pages the box lives on).
    ParameterInitBox::setReconnectHandler(this, [this](const ConnectionSettings& settings) {
        QTimer::singleShot(0, this, [this, settings] { connectTo(settings); });
    });
    m_pages = new DrivePages(this); // before the menus: they ask it for the selection
    m_menus = new MainMenus(
        this, m_docks, [this] { return m_pages->selected(); }, [this] { return m_settings; });
    connect(m_pages, &DrivePages::sameFamilySelected, m_menus->multiWriteAction(),
            &QAction::setEnabled);
    auto* eolMenu = new EolMenu(m_menus->eolMenu(), this, [this] { return m_drives; });
    m_production = new ProductionMode(
        this, m_splitter, column, m_menus->editingMenus(), [this] { return m_client.get(); },
        m_log.get());
    eolMenu->setAccess(m_production->station()->access());
    m_menus->viewMenu()->addSeparator();
    m_menus->viewMenu()->addAction(m_production->toggleAction());
    m_menus->viewMenu()->addAction(m_production->fullScreenAction());
    m_menus->viewMenu()->addAction(m_production->stationNameAction());
    // STOP ALL's keys work everywhere in the program, modal dialogs included; the button itself
    // is made per connection.
    new StopAllKeys([this] { return m_stopAll; }, this);
    m_geometry.restore();
}

MainWindow::~MainWindow()
{
    teardown();
}

void MainWindow::teardown()
{
    m_reconnection->keepView(); // the drives, selection and page a reconnection brings back
    // The pages watch drives through the hub and use their sessions: gone before them.
    m_pages->clear();
    delete m_recall; // before the drives: it remembers what is left of them
    m_recall = nullptr;
    m_docks->clear();
    delete m_hub; // before the drives: its monitors use their sessions
    m_hub = nullptr;
    if (m_stopAllAction) {
        m_menus->toolbar()->removeAction(m_stopAllAction);
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
    m_connected = false;
    m_status->reset();
    // A start confirmed for this bus says nothing about the next one (another machine may use
    // the same machine numbers).
    TestRunPanel::forgetConfirmations();
}

void MainWindow::connectTo(const ConnectionSettings& settings,
                           const QHash<int, QString>& knownTypes)
{
    // A unit being tested on this bus is ended first (its motors stopped), if the user agrees.
    if (m_production &&
        m_production->guard(tr("connect elsewhere"), freshStatusThen([this, settings, knownTypes] {
                                connectTo(settings, knownTypes);
                            })))
        return;
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
    // A bus that never opened offers nothing: no scan, no drives last seen, no pages. Later,
    // as this may run inside the failed client's own signal.
    if (m_client)
        QTimer::singleShot(0, this, [this] {
            if (!m_connected && !m_candidate)
                teardown();
        });
    m_fixedLineScanPending = false;
    m_reconnection->refused(error);
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
    m_docks->fill(m_drives, m_hub, m_groups, m_panel);
    // The traffic log names parameters and who else a write reaches (group children).
    TrafficDescriber describer(m_drives, ProfileRegistry::builtIn());
    m_log->setDescriber(describer.describer());
    connect(m_groups, &BusGroupTracker::groupsChanged, m_groups,
            [describer, groups = m_groups]() mutable { describer.setGroups(groups->groups()); });
    // STOP ALL is always on the toolbar and on the keyboard (StopAllButton::shortcuts()).
    m_stopAll = new StopAllButton(m_drives, m_menus->toolbar());
    m_stopAllAction = m_menus->toolbar()->addWidget(m_stopAll);
    // The station's recipe knows its machine numbers: STOP ALL checks them, scanned or not.
    m_stopAll->setExpectedDrives([this] {
        QVector<QPair<int, QString>> drives;
        const EolStation* station = m_production ? m_production->station() : nullptr;
        if (station && station->hasRecipe())
            for (const RecipePosition& p : station->recipe().positions)
                drives.append({p.machineNumber, p.family});
        return drives;
    });
    // No way out of this bus (quit, another connection) leaves a motor running unannounced.
    m_exitGuard = new ExitGuard(m_drives, m_poller, this);
    m_exitGuard->setLostLinkQuestion([this](const QString& leaving, std::function<void()> proceed) {
        m_reconnection->askLeaving(leaving, std::move(proceed));
    });
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
    connect(m_drives, &BusDrives::driveChanged, m_pages, &DrivePages::retitle);
    // A group setup that is wrong is said where the engineer looks, not only in its view.
    connect(m_groups, &BusGroupTracker::groupsChanged, this, [this] {
        const QVector<BusGroups::Problem> problems = m_groups->groups().problems();
        if (!problems.isEmpty())
            statusBar()->showMessage(tr("Communication groups: %1 (Bus › Communication groups)")
                                         .arg(BusGroups::describe(problems.first())),
                                     15000);
    });
    const bool simulated = settings.kind == ConnectionSettings::Kind::Simulated;
    m_status->setSimulated(simulated);
    connect(m_banner, &AlarmBanner::showAlarms, this, &MainWindow::showAlarmsOf);
    // STOP ALL may end in alarms (or clear a run that hid one): the open page reads again.
    connect(m_stopAll, &StopAllButton::finished, this, [this] {
        if (AlarmsPage* page = m_pages->alarmsPage())
            page->refresh();
    });
    // The placeholder of the first connection; on a reconnection the old panel is gone and
    // the first widget is the workspace, which stays.
    if (m_splitter->widget(0) != m_workspace)
        delete m_splitter->widget(0);
    m_splitter->insertWidget(0, m_panel);
    m_splitter->setStretchFactor(0, 0);
    m_geometry.divide(m_panel);
    connect(m_panel, &BusPanel::selectionChanged, m_pages, &DrivePages::showDrive);
    // A scan found nothing: reconnect at the DC controller's fixed potentiometer-mode settings
    // and ask its address (FixedLineHint), once the new connection is up.
    connect(m_panel, &BusPanel::fixedLineRescanRequested, this, [this] {
        // Later: the panel asking is replaced by the new connection's.
        QTimer::singleShot(0, this, [this] {
            m_fixedLineScanPending = true;
            connectTo(FixedLineHint::dcPotentiometer().applyTo(m_settings));
        });
    });
    connect(m_client.get(), &ModbusClient::connectionLost, this, [this](const QString& lost) {
        m_connected = false; // nothing to keep when another connection is tried
        setConnectionText(tr("Connection lost: %1").arg(lost), true);
        // Every live view greys at once, before the message is read.
        setLinkUp(false, tr("Connection lost: %1").arg(lost));
        // What was known of the drives, said at once, and Reconnect.
        m_reconnection->lost(ConnectionDialog::explainOpenError(m_settings, lost));
    });
    setWindowTitle(simulated
                       ? tr("OpenTOP — SIMULATED BUS (no hardware) — %1").arg(m_client->describe())
                       : tr("OpenTOP — %1").arg(m_client->describe()));
    setConnectionText(tr("Connecting to %1…").arg(m_client->describe()), false);
    m_reconnection->adopted(settings);
}

void MainWindow::setConnectionText(const QString& text, bool problem)
{
    m_status->setText(text, problem);
}

void MainWindow::setLinkUp(bool up, const QString& why)
{
    m_connected = up;
    if (m_drives)
        m_drives->setLinkUp(up);
    m_status->setLinkUp(up, why);
    emit linkChanged(up);
}

void MainWindow::onOpened(bool ok, const QString& error)
{
    setLinkUp(ok, ok ? tr("Connected: %1").arg(m_client->describe())
                     : tr("Not connected: %1").arg(error));
    if (!ok) {
        refuseConnection(m_settings, error);
        return;
    }
    if (m_settings.kind == ConnectionSettings::Kind::Simulated)
        setConnectionText(tr("Connected: %1 (simulated, no hardware)").arg(m_client->describe()),
                          false);
    else // with what the serial driver accepted
        m_status->setConnected(m_client->describe(), m_client->lineReport());
    m_poller->start();
    identifyKnown();
    if (m_fixedLineScanPending && m_panel) {
        const int slave = FixedLineHint::dcPotentiometer().slave();
        m_panel->startScan(slave, slave);
    }
    m_fixedLineScanPending = false;
    m_reconnection->opened();
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

void MainWindow::monitorAll()
{
    if (!m_drives)
        return;
    m_docks->monitorAll(m_drives->slaves());
}

std::function<void()> MainWindow::freshStatusThen(std::function<void()> then)
{
    // After a unit is cancelled, the drives' status must be read again before the exit check
    // looks at it: the run has just stopped its motors.
    return [this, then = std::move(then)] {
        if (m_poller)
            m_poller->afterFreshCycle(this, then);
        else
            then();
    };
}

void MainWindow::disconnectBus()
{
    if (m_production &&
        m_production->guard(tr("disconnect"), freshStatusThen([this] { disconnectBus(); })))
        return;
    if (!m_drives)
        return;
    // As on quitting: running drives and drives left in communication priority are named first.
    const auto close = [this] {
        teardown();
        setConnectionText(tr("Not connected (disconnected)"), false);
        emit connectionChanged(false);
    };
    checkLeaving(tr("disconnect"), close);
}

void MainWindow::checkLeaving(const QString& leaving, std::function<void()> proceed)
{
    if (m_exitGuard)
        m_exitGuard->check(leaving, std::move(proceed));
    else // no bus, or one that never came back: only what the lost link left behind is asked
        m_reconnection->askLeaving(leaving, std::move(proceed));
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (m_production && m_production->guard(tr("quit"), freshStatusThen([this] { close(); }))) {
        event->ignore();
        return;
    }
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
    // Drives running or left in communication priority, or left so when the link dropped: ask
    // first (outside this event).
    if (!m_leavingChecked &&
        ((m_exitGuard && m_exitGuard->wouldAsk()) || m_reconnection->wouldAsk())) {
        event->ignore();
        QTimer::singleShot(0, this, [this] {
            checkLeaving(tr("quit"), [this] {
                m_leavingChecked = true;
                close();
            });
        });
        return;
    }
    m_geometry.save();
    event->accept();
}

} // namespace opentop
