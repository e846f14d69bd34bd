#pragma once

#include "model/bus/BusGroups.h"

#include <QHash>
#include <optional>

namespace opentop {

// A planned set of communication groups and the order to write it in. A write of the group
// setting to a parent is executed by its children too, so a drive with children is written
// last; whatever a write changed on a child is seen again (re-read) before the next step.
class GroupPlan
{
public:
    // The group each drive should have (nullopt: disabled).
    void want(int slave, std::optional<int> group) { m_wanted.insert(slave, group); }
    bool contains(int slave) const { return m_wanted.contains(slave); }
    std::optional<int> wanted(int slave) const { return m_wanted.value(slave); }
    QVector<int> drives() const; // ascending

    // Drives whose setting differs from the plan, ascending.
    QVector<int> differences(const BusGroups& current) const;
    // The drive to write next: one whose write reaches no other drive if there is one, else
    // the first that differs; nullopt when the bus holds the plan.
    std::optional<int> nextWrite(const BusGroups& current) const;
    struct Step
    {
        int slave;
        std::optional<int> group;
        QVector<int> reaches; // the children that execute this write too
    };
    // The writes nextWrite() will choose if every drive executes them as expected (children
    // included), for telling the user beforehand; at most 2 × drives + 2 steps.
    QVector<Step> steps(const BusGroups& current) const;
    // The plan as it will look: problems it would have (chains, missing parents).
    BusGroups result(const BusGroups& current) const;

private:
    QHash<int, std::optional<int>> m_wanted;
};

} // namespace opentop
