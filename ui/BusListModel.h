#pragma once

#include "DeviceInfo.h"

#include <QAbstractTableModel>
#include <QVector>

namespace opentop {

// The drives on the bus, one row per machine number, as identification finds them.
class BusListModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column
    {
        MachineNumber,
        Switches,
        Family,
        Model,
        Firmware,
        State,
        ColumnCount
    };

    explicit BusListModel(QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

    // Adds or updates the row of info.slave, keeping rows sorted by machine number.
    void upsert(const DeviceInfo& info);
    void clear();
    const DeviceInfo* device(int row) const;
    int rowOf(int slave) const;

private:
    QVector<DeviceInfo> m_devices;
};

} // namespace opentop
