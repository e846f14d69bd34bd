#pragma once

#include <QObject>
#include <QVector>

class QDockWidget;
class QMainWindow;

namespace opentop {

class BusDrives;
class BusGroupTracker;
class BusOverview;
class BusPanel;
class GroupsView;
class MonitorHub;
class TrafficLog;
class TrendPanel;

// The main window's bottom docks: the traffic log, and the live views of the whole bus (bus
// overview, trends, communication groups) whose contents are made per connection. They share
// one place as tabs.
class BusDocks : public QObject
{
    Q_OBJECT
public:
    // Adds the docks to `window` (hidden; the window restores what was shown).
    BusDocks(QMainWindow* window, TrafficLog* log);

    QDockWidget* dock(const QString& name) const;
    // The bottom docks' height when first opened: a fifth of the window, or what they need.
    static int firstHeight(QMainWindow* window);
    // The live views of a connection's bus, in place of "Not connected".
    void fill(BusDrives* drives, MonitorHub* hub, BusGroupTracker* groups, BusPanel* panel);
    // Back to "Not connected" (the views are deleted).
    void clear();
    // Shows the bus overview and, in a window of its own, the trends of `slaves`.
    void monitorAll(const QVector<int>& slaves);

    BusOverview* overview() const { return m_overview; }
    TrendPanel* trends() const { return m_trends; }
    GroupsView* groupsView() const { return m_groupsView; }

private:
    void replace(const QString& name, QWidget* widget);

    QMainWindow* m_window;
    BusOverview* m_overview = nullptr;
    TrendPanel* m_trends = nullptr;
    GroupsView* m_groupsView = nullptr;
    bool m_bottomSized = false; // the bottom docks were given their first height
};

} // namespace opentop
