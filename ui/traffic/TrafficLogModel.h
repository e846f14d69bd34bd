#pragma once

#include "transport/TrafficEntry.h"

#include <QAbstractTableModel>
#include <QVector>
#include <deque>

namespace opentop {

// The frames shown by the traffic log view, oldest first, at most `capacity` of them.
class TrafficLogModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column
    {
        Time,
        Direction,
        Slave,
        Function,
        Bytes,
        Error,
        Meaning, // last: it takes the width that is left
        ColumnCount
    };
    enum Role
    {
        SlaveRole = Qt::UserRole + 1, // int
        DirectionRole,                // int(TrafficEntry::Direction)
        ErrorRole,                    // bool: an error or an exception reply
    };

    explicit TrafficLogModel(int capacity, QObject* parent = nullptr);

    void append(const TrafficEntry& entry);
    void append(const QVector<TrafficEntry>& entries);
    void clear();
    const TrafficEntry& entry(int row) const { return m_entries[size_t(row)]; }
    int capacity() const { return m_capacity; }
    // True for frames that went wrong: an error, or an exception reply.
    static bool isError(const TrafficEntry& entry);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

private:
    std::deque<TrafficEntry> m_entries;
    int m_capacity;
};

} // namespace opentop
