#pragma once

#include <QObject>

class QAction;
class QSplitter;
class QToolBar;
class QWidget;

namespace opentop {

class AlarmBanner;
class BusDocks;
class BusDrives;
class BusGroupTracker;
class BusPanel;
class BusRecallBar;
class DrivePages;
class DriveStatusPoller;
class MainWindow;
class MonitorHub;
class StopAllButton;
struct ConnectionSettings;

// What the main window shows of one connection's bus, made when the window adopts a connection
// and deleted in order before its drives: the bus list (left of the drive's pages), the
// monitoring the live views share, the docks' live views, STOP ALL on the toolbar, the alarm
// banner and the bar offering the drives last seen; and the drive's pages following them. The
// connection itself stays the window's.
class ConnectionViews : public QObject
{
    Q_OBJECT
public:
    // `central`: the window's column (the banner and the recall bar go above `splitter`);
    // `pages`: the drive's pages, which follow the bus list's selection.
    ConnectionViews(MainWindow* window, QWidget* central, QSplitter* splitter, BusDocks* docks,
                    DrivePages* pages);

    // The views of a new connection's drives; `offerRecall`: whether the recall bar offers the
    // drives last seen (not when the caller names the drives).
    void make(BusDrives* drives, DriveStatusPoller* poller, BusGroupTracker* groups,
              QToolBar* toolbar, const ConnectionSettings& settings, bool offerRecall);
    // Deletes them (before the drives they watch).
    void clear();

    BusPanel* panel() const { return m_panel; }
    MonitorHub* hub() const { return m_hub; }
    StopAllButton* stopAll() const { return m_stopAll; }
    BusRecallBar* recall() const { return m_recall; }

private:
    MainWindow* m_window;
    QWidget* m_central;
    QSplitter* m_splitter;
    BusDocks* m_docks;
    DrivePages* m_pages;
    QToolBar* m_toolbar = nullptr;
    BusPanel* m_panel = nullptr;
    MonitorHub* m_hub = nullptr;
    AlarmBanner* m_banner = nullptr;
    StopAllButton* m_stopAll = nullptr;
    QAction* m_stopAllAction = nullptr;
    BusRecallBar* m_recall = nullptr;
};

} // namespace opentop
