#include "ui/main/MainWindow.h"

#include "model/bus/BusDrives.h"
#include "model/bus/BusGroupTracker.h"
#include "model/bus/DriveStatusPoller.h"
#include "model/bus/FixedLineHint.h"
#include "model/profile/ProfileRegistry.h"
#include "model/session/DeviceIdentifier.h"
#include "model/station/EolStation.h"
#include "model/traffic/TrafficDescriber.h"
#include "transport/ModbusClient.h"
#include "transport/TrafficLog.h"
#include "ui/bus/BusPanel.h"
#include "ui/bus/BusRecallBar.h"
#include "ui/connection/ConnectionDialog.h"
#include "ui/eol/EolMenu.h"
#include "ui/eol/ProductionMode.h"
#include "ui/main/LinkBar.h"
#include "ui/main/MainMenus.h"
#include "ui/main/Reconnection.h"
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
#include <QVBoxLayout>

namespace opentop {

MainWindow::MainWindow(ClientFactory factory, QWidget* parent)
    : QMainWindow(parent)
    , m_factory(std::move(factory))
    , m_log(std::make_unique<TrafficLog>())
    , m_pending(
          [this](std::unique_ptr<ModbusClient> client, const ConnectionSettings& settings,
                 const QHash<int, QString>& knownTypes) {
              adopt(std::move(client), settings, knownTypes);
              onOpened(true, QString());
          },
          [this](const ConnectionSettings& failed, const QString& why) {
              refuseConnection(failed, why);
          })
    , m_workspace(new DriveWorkspace(this))
    , m_central(new QWidget(this))
    , m_splitter(new QSplitter(this))
    , m_status(new ConnectionStatus(this))
    , m_geometry(this, m_splitter)
    , m_reconnection(new Reconnection(this))
    , m_leaving(new BusLeaving(this))
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
    m_views = new ConnectionViews(this, m_central, m_splitter, m_docks, m_pages);
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
    new StopAllKeys([this] { return m_views->stopAll(); }, this);
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
    m_views->clear();
    m_leaving->release();
    m_log->setDescriber({});
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
    if (m_leaving->unitHolds(tr("connect elsewhere"),
                             [this, settings, knownTypes] { connectTo(settings, knownTypes); }))
        return;
    // A start confirmed for this bus says nothing about the next one.
    TestRunPanel::forgetConfirmations();
    m_pending.drop();
    QString error;
    std::unique_ptr<ModbusClient> client = m_factory(settings, m_log.get(), &error);
    if (!client) {
        refuseConnection(settings, error);
        return;
    }
    // The working connection stays until the new one is open, where it can (PendingConnection).
    if (m_connected && PendingConnection::canWait(m_settings, settings)) {
        m_status->setText(tr("Connecting to %1… (still connected to %2)")
                              .arg(client->describe(), m_client->describe()),
                          false);
        m_pending.open(std::move(client), settings, knownTypes);
        return;
    }
    adopt(std::move(client), settings, knownTypes);
    connect(m_client.get(), &ModbusClient::opened, this, &MainWindow::onOpened);
    m_client->open();
}

void MainWindow::refuseConnection(const ConnectionSettings& settings, const QString& error)
{
    const QString why = ConnectionDialog::explainOpenError(settings, error);
    if (m_connected && m_client) {
        // The bus one was working on stays as it was.
        m_status->setText(
            tr("Connected: %1 (the new connection failed: %2)").arg(m_client->describe(), error),
            true);
        QMessageBox::warning(
            this, tr("Cannot connect"),
            tr("%1\n\nStill connected to %2; nothing was changed.").arg(why, m_client->describe()));
        return;
    }
    m_status->setText(tr("Not connected: %1").arg(error), true);
    // A bus that never opened offers nothing: no scan, no drives last seen, no pages. Later,
    // as this may run inside the failed client's own signal.
    if (m_client)
        QTimer::singleShot(0, this, [this] {
            if (!m_connected && !m_pending.isOpening())
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
    // The drives last seen here are offered back, but not when the caller names the drives.
    m_views->make(m_drives, m_poller, m_groups, m_menus->toolbar(), settings, knownTypes.isEmpty());
    // The traffic log names parameters and who else a write reaches (group children).
    TrafficDescriber describer(m_drives, ProfileRegistry::builtIn());
    m_log->setDescriber(describer.describer());
    connect(m_groups, &BusGroupTracker::groupsChanged, m_groups,
            [describer, groups = m_groups]() mutable { describer.setGroups(groups->groups()); });
    m_leaving->watch(m_drives, m_poller);
    connect(m_views->recall(), &BusRecallBar::restoreRequested, this,
            [this](const QHash<int, QString>& types) {
                m_knownTypes = types;
                if (m_connected)
                    identifyKnown();
            });
    const bool simulated = settings.kind == ConnectionSettings::Kind::Simulated;
    m_status->setSimulated(simulated);
    m_geometry.divide(m_views->panel());
    // A scan found nothing: reconnect at the DC controller's fixed potentiometer-mode settings
    // and ask its address (FixedLineHint), once the new connection is up.
    connect(m_views->panel(), &BusPanel::fixedLineRescanRequested, this, [this] {
        // Later: the panel asking is replaced by the new connection's.
        QTimer::singleShot(0, this, [this] {
            m_fixedLineScanPending = true;
            connectTo(FixedLineHint::dcPotentiometer().applyTo(m_settings));
        });
    });
    connect(m_client.get(), &ModbusClient::connectionLost, this, [this](const QString& lost) {
        m_connected = false; // nothing to keep when another connection is tried
        m_status->setText(tr("Connection lost: %1").arg(lost), true);
        // Every live view greys at once, before the message is read.
        setLinkUp(false, tr("Connection lost: %1").arg(lost));
        // What was known of the drives, said at once, and Reconnect.
        m_reconnection->lost(ConnectionDialog::explainOpenError(m_settings, lost));
    });
    setWindowTitle(simulated
                       ? tr("OpenTOP — SIMULATED BUS (no hardware) — %1").arg(m_client->describe())
                       : tr("OpenTOP — %1").arg(m_client->describe()));
    m_status->setText(tr("Connecting to %1…").arg(m_client->describe()), false);
    m_reconnection->adopted(settings);
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
        m_status->setText(tr("Connected: %1 (simulated, no hardware)").arg(m_client->describe()),
                          false);
    else // with what the serial driver accepted
        m_status->setConnected(m_client->describe(), m_client->lineReport());
    m_poller->start();
    identifyKnown();
    if (m_fixedLineScanPending && m_views->panel()) {
        const int slave = FixedLineHint::dcPotentiometer().slave();
        m_views->panel()->startScan(slave, slave);
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

void MainWindow::disconnectBus()
{
    if (m_leaving->unitHolds(tr("disconnect"), [this] { disconnectBus(); }))
        return;
    if (!m_drives)
        return;
    // As on quitting: running drives and drives left in communication priority are named first.
    const auto close = [this] {
        teardown();
        m_status->setText(tr("Not connected (disconnected)"), false);
        emit connectionChanged(false);
    };
    checkLeaving(tr("disconnect"), close);
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (!m_leaving->mayClose()) {
        event->ignore();
        return;
    }
    m_geometry.save();
    event->accept();
}

} // namespace opentop
