#include "ui/traffic/TrafficLogFilter.h"

#include "transport/TrafficEntry.h"
#include "ui/traffic/TrafficLogModel.h"

namespace opentop {

TrafficLogFilter::TrafficLogFilter(QObject* parent)
    : QSortFilterProxyModel(parent)
{
}

void TrafficLogFilter::setSlave(int slave)
{
    m_slave = slave;
    invalidateFilter();
}

void TrafficLogFilter::setDirection(DirectionFilter direction)
{
    m_direction = direction;
    invalidateFilter();
}

void TrafficLogFilter::setErrorsOnly(bool errorsOnly)
{
    m_errorsOnly = errorsOnly;
    invalidateFilter();
}

bool TrafficLogFilter::filterAcceptsRow(int sourceRow, const QModelIndex& sourceParent) const
{
    const QModelIndex index = sourceModel()->index(sourceRow, 0, sourceParent);
    if (m_slave >= 0 && index.data(TrafficLogModel::SlaveRole).toInt() != m_slave)
        return false;
    if (m_errorsOnly && !index.data(TrafficLogModel::ErrorRole).toBool())
        return false;
    const auto direction =
        TrafficEntry::Direction(index.data(TrafficLogModel::DirectionRole).toInt());
    switch (m_direction) {
    case DirectionFilter::All:
        return true;
    case DirectionFilter::Tx:
        return direction == TrafficEntry::Direction::Tx;
    case DirectionFilter::Rx:
        return direction == TrafficEntry::Direction::Rx;
    case DirectionFilter::Events:
        return direction == TrafficEntry::Direction::Event;
    }
    return true;
}

} // namespace opentop
