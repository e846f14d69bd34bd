#include "model/bus/GroupPlan.h"

#include <algorithm>

namespace opentop {

QVector<int> GroupPlan::drives() const
{
    QVector<int> out(m_wanted.keyBegin(), m_wanted.keyEnd());
    std::sort(out.begin(), out.end());
    return out;
}

QVector<int> GroupPlan::differences(const BusGroups& current) const
{
    QVector<int> out;
    for (int slave : drives()) {
        if (current.contains(slave) && current.groupOf(slave) != m_wanted.value(slave))
            out << slave;
    }
    return out;
}

std::optional<int> GroupPlan::nextWrite(const BusGroups& current) const
{
    const QVector<int> differ = differences(current);
    if (differ.isEmpty())
        return std::nullopt;
    // A write that reaches nobody else first; among those, one whose new parent is settled
    // (a parent still to be written would pass its write on to it).
    std::optional<int> reachesNobody;
    for (int slave : differ) {
        if (!current.childrenOf(slave).isEmpty())
            continue;
        const std::optional<int> group = m_wanted.value(slave);
        const bool parentSettled = !group || *group == slave || !differ.contains(*group);
        if (parentSettled)
            return slave;
        if (!reachesNobody)
            reachesNobody = slave;
    }
    return reachesNobody ? reachesNobody : differ.first();
}

QVector<GroupPlan::Step> GroupPlan::steps(const BusGroups& current) const
{
    QVector<Step> out;
    BusGroups bus = current;
    const int limit = 2 * int(bus.drives().size()) + 2;
    while (out.size() < limit) {
        const std::optional<int> next = nextWrite(bus);
        if (!next)
            break;
        Step step{*next, m_wanted.value(*next), bus.childrenOf(*next)};
        bus.setGroup(step.slave, step.group);
        for (int child : step.reaches)
            bus.setGroup(child, step.group);
        out << step;
    }
    return out;
}

BusGroups GroupPlan::result(const BusGroups& current) const
{
    BusGroups out = current;
    for (auto it = m_wanted.cbegin(); it != m_wanted.cend(); ++it) {
        if (out.contains(it.key()))
            out.setGroup(it.key(), it.value());
    }
    return out;
}

} // namespace opentop
