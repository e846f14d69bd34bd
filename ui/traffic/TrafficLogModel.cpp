#include "ui/traffic/TrafficLogModel.h"

#include "transport/RtuFrame.h"

#include <QBrush>
#include <QColor>
#include <algorithm>

namespace opentop {

TrafficLogModel::TrafficLogModel(int capacity, QObject* parent)
    : QAbstractTableModel(parent)
    , m_capacity(capacity > 0 ? capacity : 1)
{
}

void TrafficLogModel::append(const TrafficEntry& entry)
{
    append(QVector<TrafficEntry>{entry});
}

void TrafficLogModel::append(const QVector<TrafficEntry>& entries)
{
    if (entries.isEmpty())
        return;
    // One removal and one insertion per batch: views re-lay out once, not once per frame.
    const int incoming = std::min(int(entries.size()), m_capacity);
    const int excess = int(m_entries.size()) + incoming - m_capacity;
    if (excess > 0) {
        beginRemoveRows(QModelIndex(), 0, excess - 1);
        m_entries.erase(m_entries.begin(), m_entries.begin() + excess);
        endRemoveRows();
    }
    const int row = int(m_entries.size());
    beginInsertRows(QModelIndex(), row, row + incoming - 1);
    for (auto it = entries.cend() - incoming; it != entries.cend(); ++it)
        m_entries.push_back(*it);
    endInsertRows();
}

void TrafficLogModel::clear()
{
    beginResetModel();
    m_entries.clear();
    endResetModel();
}

bool TrafficLogModel::isError(const TrafficEntry& entry)
{
    return !entry.error.isEmpty() ||
           (entry.direction == TrafficEntry::Direction::Rx && (entry.function & 0x80));
}

int TrafficLogModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : int(m_entries.size());
}

int TrafficLogModel::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant TrafficLogModel::data(const QModelIndex& index, int role) const
{
    if (!index.isValid() || index.row() >= rowCount())
        return {};
    const TrafficEntry& e = entry(index.row());
    switch (role) {
    case SlaveRole:
        return int(e.slave);
    case DirectionRole:
        return int(e.direction);
    case ErrorRole:
        return isError(e);
    case Qt::BackgroundRole:
        return isError(e) ? QVariant(QBrush(QColor(255, 205, 205))) : QVariant();
    case Qt::ForegroundRole:
        return isError(e) ? QVariant(QBrush(Qt::black)) : QVariant();
    case Qt::ToolTipRole:
        return e.toLine();
    case Qt::DisplayRole:
        break;
    default:
        return {};
    }
    switch (index.column()) {
    case Time:
        return e.time.toString(QStringLiteral("HH:mm:ss.zzz"));
    case Direction:
        switch (e.direction) {
        case TrafficEntry::Direction::Tx:
            return tr("Tx");
        case TrafficEntry::Direction::Rx:
            return tr("Rx");
        case TrafficEntry::Direction::Event:
            return tr("–");
        }
        return {};
    case Slave:
        return int(e.slave);
    case Function:
        return QStringLiteral("%1").arg(uint(e.function), 2, 16, QLatin1Char('0')).toUpper();
    case Bytes:
        return RtuFrame::toHex(e.bytes);
    case Meaning:
        if (e.responseMs >= 0)
            return tr("%1 (%2 ms)").arg(e.summary).arg(e.responseMs, 0, 'f', 1);
        return e.summary;
    case Error:
        return e.error;
    default:
        return {};
    }
}

QVariant TrafficLogModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Time:
        return tr("Time");
    case Direction:
        return tr("Direction");
    case Slave:
        return tr("Drive");
    case Function:
        return tr("Function");
    case Bytes:
        return tr("Bytes");
    case Meaning:
        return tr("Meaning");
    case Error:
        return tr("Error");
    default:
        return {};
    }
}

} // namespace opentop
