#include "BusListModel.h"

#include <QBrush>
#include <QColor>
#include <algorithm>

namespace opentop {

BusListModel::BusListModel(QObject* parent)
    : QAbstractTableModel(parent)
{
}

int BusListModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : m_devices.size();
}

int BusListModel::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant BusListModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case MachineNumber:
        return tr("Machine no.");
    case Switches:
        return tr("Hex / switches");
    case Family:
        return tr("Family");
    case Model:
        return tr("Model");
    case Firmware:
        return tr("Firmware");
    case State:
        return tr("State");
    }
    return {};
}

QVariant BusListModel::data(const QModelIndex& index, int role) const
{
    if (!index.isValid() || index.row() >= m_devices.size())
        return {};
    const DeviceInfo& d = m_devices[index.row()];
    if (role == Qt::DisplayRole) {
        switch (index.column()) {
        case MachineNumber:
            return d.slave;
        case Switches:
            return DeviceInfo::hexText(d.slave) + QStringLiteral("  ") +
                   DeviceInfo::switchText(d.slave);
        case Family:
            return d.family.isEmpty() ? tr("—") : d.family.toUpper();
        case Model:
            return d.variant.isEmpty() && d.state == DeviceInfo::State::Present &&
                           !d.detail.isEmpty()
                       ? tr("%1 — variant unknown").arg(d.family.toUpper())
                       : d.model;
        case Firmware:
            return d.firmware.isEmpty() ? tr("—") : tr("V%1").arg(d.firmware);
        case State:
            return DeviceInfo::stateText(d.state);
        }
    }
    if (role == Qt::ToolTipRole)
        return d.detail;
    if (role == Qt::ForegroundRole && index.column() == State) {
        switch (d.state) {
        case DeviceInfo::State::Present:
            return QBrush(QColor(0x1b, 0x7f, 0x2a));
        case DeviceInfo::State::Garbled:
        case DeviceInfo::State::Absent:
            return QBrush(QColor(0xb0, 0x1c, 0x1c));
        default:
            return {};
        }
    }
    if (role == Qt::TextAlignmentRole && index.column() == MachineNumber)
        return int(Qt::AlignRight | Qt::AlignVCenter);
    return {};
}

void BusListModel::upsert(const DeviceInfo& info)
{
    const int existing = rowOf(info.slave);
    if (existing >= 0) {
        m_devices[existing] = info;
        emit dataChanged(index(existing, 0), index(existing, ColumnCount - 1));
        return;
    }
    const auto pos =
        std::lower_bound(m_devices.begin(), m_devices.end(), info.slave,
                         [](const DeviceInfo& d, int slave) { return d.slave < slave; });
    const int row = int(pos - m_devices.begin());
    beginInsertRows({}, row, row);
    m_devices.insert(row, info);
    endInsertRows();
}

void BusListModel::clear()
{
    beginResetModel();
    m_devices.clear();
    endResetModel();
}

const DeviceInfo* BusListModel::device(int row) const
{
    return row >= 0 && row < m_devices.size() ? &m_devices[row] : nullptr;
}

int BusListModel::rowOf(int slave) const
{
    for (int i = 0; i < m_devices.size(); ++i) {
        if (m_devices[i].slave == slave)
            return i;
    }
    return -1;
}

} // namespace opentop
