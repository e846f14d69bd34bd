#pragma once

#include <QSet>
#include <QWidget>

class QComboBox;
class QPushButton;
class QTreeWidget;
class QTreeWidgetItem;

namespace opentop {

class MonitorHub;
class TrendChart;

// The "Trends" dock: which quantities of which drives to chart (a checkable tree), the poll
// rate shared by every live view of the bus, the time window, pause, live, markers and export,
// and the chart itself.
class TrendPanel : public QWidget
{
    Q_OBJECT
public:
    explicit TrendPanel(MonitorHub* hub, QWidget* parent = nullptr);

    // Charts speed, target and load of `slaves` only (the selected drives).
    void showDrives(const QVector<int>& slaves);
    TrendChart* chart() const { return m_chart; }
    QTreeWidget* tree() const { return m_tree; }
    // Checks or unchecks one quantity of a drive; false when the tree does not have it.
    bool setChecked(int slave, const QString& key, bool checked);
    // Poll rates offered, in milliseconds between polls of a drive.
    static QVector<int> pollIntervals();
    static QString pollRateText(int ms);

private:
    using Key = QPair<int, QString>;

    void rebuildTree();
    QSet<Key> defaultsFor(int slave) const;
    void applyChecks();
    void syncRate(int ms);
    void exportCsvClicked();
    void exportPngClicked();

    MonitorHub* m_hub;
    TrendChart* m_chart;
    QTreeWidget* m_tree;
    QComboBox* m_rate;
    QComboBox* m_window;
    QPushButton* m_pause;
    QPushButton* m_live;
    QSet<Key> m_checked;
    QSet<int> m_known; // drives in the tree, whose checks are the user's
    QVector<int> m_selected;
    bool m_preselected = false;
    bool m_updating = false;
};

} // namespace opentop
