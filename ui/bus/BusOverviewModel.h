#pragma once

#include "monitor/DeviceMonitor.h"

#include <QAbstractTableModel>
#include <QHash>
#include <QTimer>
#include <QVector>

namespace opentop {

class BusDrives;
class MonitorHub;

// Every drive on the bus in one table, live from the MonitorHub: state and direction, speed
// (r/min and the drive's display unit), target, load, the active alarm and when the drive
// last answered. Rows are the drives with a profile, by machine number.
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
    QString text(int slave, Column column) const;

private:
    void rebuild();
    QString cell(int slave, int column) const;

    BusDrives* m_drives;
    MonitorHub* m_hub;
    QVector<int> m_slaves;
    QHash<int, QString> m_errors; // the last poll failed: why
    QTimer m_refresh;
    QTimer m_age; // the ages follow the clock, also when no sample comes
};

} // namespace opentop
