#pragma once

#include "transport/ConnectionSettings.h"
#include "ui/main/BusDocks.h"
#include "ui/main/BusLeaving.h"
#include "ui/main/ConnectionStatus.h"
#include "ui/main/ConnectionViews.h"
#include "ui/main/DrivePages.h"
#include "ui/main/PendingConnection.h"
#include "ui/main/WindowGeometry.h"

#include <QHash>
#include <QMainWindow>
#include <QVector>
#include <functional>
#include <memory>

class QLabel;
class QSplitter;

namespace opentop {

class AlarmsPage;
class BusDrives;
class BusGroupTracker;
class BusOverview;
class BusPanel;
class BusRecallBar;
class DriveStatusPoller;
class DriveWorkspace;
class ExitGuard;
class GroupsView;
class MainMenus;
class ModbusClient;
class MonitorHub;
class ProductionMode;
class Reconnection;
class StatusLight;
class StopAllButton;
class TrafficLog;
class TrendPanel;

// The main window: the bus on the left (scan, drives, status lights), the selected drive's
// pages on the right. It owns the connection; all bus work happens on the client's worker
// thread and comes back asynchronously, so the window never waits on the wire.
// Its parts live beside it: MainMenus, DrivePages, BusDocks, ConnectionViews, ConnectionStatus,
// PendingConnection, BusLeaving (every way out of the bus), WindowGeometry.
class MainWindow : public QMainWindow
{
    Q_OBJECT
public:
    // Makes a client for a connection (the program's backends live outside ui/).
    // Every frame of the connection goes to `log`.
    using ClientFactory = std::function<std::unique_ptr<ModbusClient>(
        const ConnectionSettings&, TrafficLog* log, QString* error)>;

    MainWindow(ClientFactory factory, QWidget* parent = nullptr);
    ~MainWindow() override;

    // Opens `settings` (closing the current connection). `knownTypes`: drives said to be at
    // these machine numbers (a simulated bus's list); they are identified at once, and their
    // variants used where a drive does not report its own.
    void connectTo(const ConnectionSettings& settings, const QHash<int, QString>& knownTypes = {});
    // Bus > Disconnect: closes the connection after the exit check (running drives and drives
    // left in communication priority are named first, stopped and given back by default).
    void disconnectBus();
    // Every way out of this bus asks here first: the exit question over a live link
    // (ExitGuard), the lost link's over a dead one (Reconnection); `proceed` when answered.
    void checkLeaving(const QString& leaving, std::function<void()> proceed)
    {
        m_leaving->check(leaving, std::move(proceed));
    }
    // Coming back from a lost link: Bus > Reconnect (Ctrl+R), the link bar, the last connection.
    Reconnection* reconnection() const { return m_reconnection; }
    bool isConnected() const { return m_connected; }
    ModbusClient* client() const { return m_client.get(); }
    BusDrives* drives() const { return m_drives; }
    BusPanel* busPanel() const { return m_views->panel(); }
    DriveWorkspace* workspace() const { return m_workspace; }
    TrafficLog* trafficLog() const { return m_log.get(); }
    StopAllButton* stopAllButton() const { return m_views->stopAll(); }
    ExitGuard* exitGuard() const { return m_leaving->exitGuard(); }
    DriveStatusPoller* statusPoller() const { return m_poller; }
    QLabel* connectionLabel() const { return m_status->label(); }
    // The link's light in the status bar: green only while connected and the link is up.
    StatusLight* linkLight() const { return m_status->light(); }
    // The selected drive's Alarms page (null when none is open).
    AlarmsPage* alarmsPage() const { return m_pages->alarmsPage(); }
    // Selects `slave` and brings its Alarms page to the front (the alarm banner's Show).
    void showAlarmsOf(int slave) { m_pages->showAlarmsOf(slave); }
    MonitorHub* monitorHub() const { return m_views->hub(); }
    BusOverview* busOverview() const { return m_docks->overview(); }
    TrendPanel* trendPanel() const { return m_docks->trends(); }
    // Every drive's communication group, kept up to date (writes to a parent re-read children).
    BusGroupTracker* groups() const { return m_groups; }
    GroupsView* groupsView() const { return m_docks->groupsView(); }
    // The offer of the drives last seen on this connection (or to scan), per connection.
    BusRecallBar* recallBar() const { return m_views->recall(); }
    // The permanent marker of a simulated bus (hidden on hardware).
    QLabel* simulatedBanner() const { return m_status->simulatedBanner(); }
    // The end-of-line operator screen and the switch to it (View > Production mode).
    ProductionMode* production() const { return m_production; }
    // Shows the bus overview and the trends of every drive (they poll while shown).
    void monitorAll();

signals:
    void connectionChanged(bool connected);
    // The open link dropped (false) or is up (true).
    void linkChanged(bool up);

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void teardown();
    // Makes `client` the window's connection (the old one closed) and builds its views; the
    // client is opened by the caller, or already open.
    void adopt(std::unique_ptr<ModbusClient> client, const ConnectionSettings& settings,
               const QHash<int, QString>& knownTypes);
    // A connection that could not be made: says why, and whether the old one is kept.
    void refuseConnection(const ConnectionSettings& settings, const QString& error);
    void onOpened(bool ok, const QString& error);
    // The link is up or down: every live view follows (monitor/Freshness).
    void setLinkUp(bool up, const QString& why);
    void identifyKnown();

    ClientFactory m_factory;
    std::unique_ptr<TrafficLog> m_log;
    ConnectionSettings m_settings;
    QHash<int, QString> m_knownTypes;
    std::unique_ptr<ModbusClient> m_client;
    PendingConnection m_pending; // a connection being opened while the working one stays
    bool m_connected = false;
    // The connection being opened is the bus panel's rescan at FixedLineHint's settings.
    bool m_fixedLineScanPending = false;
    BusDrives* m_drives = nullptr;
    DriveStatusPoller* m_poller = nullptr;
    DriveWorkspace* m_workspace;
    QWidget* m_central;
    QSplitter* m_splitter;
    ConnectionStatus* m_status; // the status bar's connection widgets
    WindowGeometry m_geometry;
    BusDocks* m_docks = nullptr;
    ConnectionViews* m_views = nullptr; // the bus list, STOP ALL, banners: per connection
    MainMenus* m_menus = nullptr;
    ProductionMode* m_production = nullptr;
    DrivePages* m_pages = nullptr;
    BusGroupTracker* m_groups = nullptr;
    Reconnection* m_reconnection;
    BusLeaving* m_leaving;
};

} // namespace opentop
