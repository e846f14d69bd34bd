#include "bus/GroupPlan.h"

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
    for (int slave : differ) {
        if (current.childrenOf(slave).isEmpty())
            return slave;
    }
    return differ.first();
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
