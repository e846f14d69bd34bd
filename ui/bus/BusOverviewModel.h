#pragma once

#include "model/monitor/DeviceMonitor.h"
#include "model/session/Freshness.h"

#include <QAbstractTableModel>
#include <QHash>
#include <QTimer>
#include <QVector>
#include <optional>

namespace opentop {

class BusDrives;
class MonitorHub;

// Every drive on the bus in one table, live from the MonitorHub: state and direction, speed
// (r/min and the drive's display unit), target, load, the active alarm and when the drive
// last answered. Rows are the drives with a profile, by machine number. The cells are worked
// out a few times a second into a cache, and only those whose text or look changed are
// reported: views repaint what changed, at that rate, however many samples arrive.
class BusOverviewModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column
    {
        Drive,
        State,
        Speed,
        DisplaySpeed,
        Target,
        Load,
        Alarm,
        Communication,
        ColumnCount
    };

    BusOverviewModel(BusDrives* drives, MonitorHub* hub, QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = QModelIndex()) const override;
    int columnCount(const QModelIndex& parent = QModelIndex()) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

    // Bool, every cell: the drive's values are not live (monitor/Freshness).
    static constexpr int StaleRole = Qt::UserRole + 1;

    QVector<int> slaves() const { return m_slaves; }
    bool isStale(int slave) const;
    int rowOf(int slave) const { return m_slaves.indexOf(slave); }
    // What the grid shows (worked out at the last refresh).
    QString text(int slave, Column column) const;

private:
    // What a row shows, as last worked out.
    struct Row
    {
        QString text[ColumnCount];
        bool stale = false;
        bool alarm = false;    // active alarm
        bool error = false;    // the last poll failed
        bool valuesDue = true; // a sample or error came since the values were worked out
    };

    void rebuild();
    // Works out the due rows' values and every row's age and look; reports what changed.
    void refresh();
    // Works out row `r` again; the columns whose text or look changed.
    QVector<int> evaluate(int r, const QDateTime& now);
    QString valueCell(int slave, int column, const std::optional<MonitorSample>& s) const;
    QString communicationCell(int slave, Freshness::State state, const QDateTime& now) const;
    void markDue(int slave);

    BusDrives* m_drives;
    MonitorHub* m_hub;
    QVector<int> m_slaves;
    QVector<Row> m_rows;          // one per slave, in m_slaves' order
    QHash<int, QString> m_errors; // the last poll failed: why
    QTimer m_refresh; // the values, the ages and the looks follow, also when no sample comes
};

} // namespace opentop
