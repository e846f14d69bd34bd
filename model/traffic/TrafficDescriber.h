#pragma once

#include "transport/TrafficLog.h"

#include <QString>
#include <functional>
#include <memory>

namespace opentop {

class BusDrives;
class BusGroups;
class Profile;
class ProfileRegistry;
struct ModbusRequest;
struct TrafficEntry;

// Adds parameter names from the device profiles to the traffic log's frame summaries:
// "read 03 0xCA03 ×1 (spno2.speed)", "→ 1000 (spno2.speed = 1000 r/min)". The profile is that of
// the family of the drive at the request's machine number.
class TrafficDescriber
{
public:
    // slave → profile (nullptr when unknown). Called on the bus thread: must be thread-safe.
    using ProfileLookup = std::function<const Profile*(int slave)>;

    explicit TrafficDescriber(ProfileLookup lookup);
    // Follows the families of `drives` (through its signals, on the GUI thread) and looks them
    // up in `registry`; the describer may then be called from any thread.
    explicit TrafficDescriber(BusDrives* drives, const ProfileRegistry& registry);

    // The communication groups of the bus: a write to a group parent is described as reaching
    // its children too. A copy is kept (thread-safe); call again when the groups change.
    void setGroups(const BusGroups& groups);

    // The summary with parameter names added, and who else a write reaches (a broadcast, a
    // group parent's children); empty when there is nothing to add.
    QString describe(const TrafficEntry& entry, const ModbusRequest* request) const;
    // For TrafficLog::setDescriber; stays valid after this object is gone.
    TrafficLog::Describer describer() const;

private:
    QString describeNames(const TrafficEntry& entry, const ModbusRequest* request) const;

    struct State;
    std::shared_ptr<State> m_state;
};

} // namespace opentop
