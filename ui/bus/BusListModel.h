#pragma once

#include "model/bus/DriveStatusPoller.h"
#include "model/session/DeviceInfo.h"

#include <QAbstractTableModel>
#include <QColor>
#include <QHash>
#include <QIcon>
#include <QTimer>
#include <QVector>

namespace opentop {

class DriveStatusPoller;

// The drives on the bus, one row per machine number, as identification finds them, with the
// status the poller reports: light, communication state and control priority.
class BusListModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column
    {
        Light,
        MachineNumber,
        Switches, // the number's switch positions, in the family's notation
        Family,
        Model,
        Firmware,
        State, // identification, then communication state once polled
        Priority,
        Name, // the user's name for the machine (shown beside the machine number)
        ColumnCount
    };
    enum Role
    {
        SlaveRole = Qt::UserRole + 1, // int, every column
        LedRole,                      // int(DriveStatus::Led), every column
        ProblemRole,                  // bool: garbled replies, likely duplicate machine number
        StaleRole,                    // bool: the status shown is not live (monitor/Freshness)
    };

    explicit BusListModel(QObject* parent = nullptr);

    // Status lights, communication state and priority come from `poller` (may be null).
    void setPoller(DriveStatusPoller* poller);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

    // Adds or updates the row of info.slave, keeping rows sorted by machine number.
    void upsert(const DeviceInfo& info);
    void remove(int slave);
    void clear();
    const DeviceInfo* device(int row) const;
    int rowOf(int slave) const;
    int slaveAt(int row) const;
    DriveStatus status(int slave) const;
    // The light shown for `slave` now: grey unless its status is live.
    DriveStatus::Led shownLed(int slave) const;
    bool isStale(int slave) const;
    // The hint shown for a garbled address: what to check.
    static QString duplicateHint(int slave);

private:
    // What a row's status columns showed when they were last reported.
    struct Look
    {
        QString state;
        QString priority;
        QRgb light = 0;
        bool stale = false;
        bool failing = false;
        bool operator==(const Look& o) const
        {
            return state == o.state && priority == o.priority && light == o.light &&
                   stale == o.stale && failing == o.failing;
        }
    };

    void statusChanged(int slave);
    Look lookOf(const DeviceInfo& d) const;
    // Reports row `row` changed when its look did: a poll that changes nothing repaints
    // nothing, nor makes the view measure every row again for its column widths.
    void reportIfChanged(int row);
    QVariant display(const DeviceInfo& d, int column) const;
    QString toolTip(const DeviceInfo& d, int column) const;
    QIcon ledIcon(const QColor& color) const; // cached by colour

    QVector<DeviceInfo> m_devices;
    DriveStatusPoller* m_poller = nullptr;
    mutable QHash<QRgb, QIcon> m_icons;
    QHash<int, Look> m_reported; // by machine number
    QTimer m_age;                // lights and ages follow the clock between polls
};

} // namespace opentop
