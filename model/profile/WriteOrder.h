#pragma once

#include <QStringList>

namespace opentop {

class Profile;

// The one order in which settings are written: each after every other one of the same write
// whose value decides its allowed values (ParameterMeta::controllingParameters), through
// chains too, and otherwise as given. A drive checks a value against what it holds at that
// moment, so a speed limit that depends on a mode is written after the mode. Used by the
// parameter pages (DeviceParameters), restore (RestorePlan) and `set`.
class WriteOrder
{
public:
    // A cycle (not possible in a valid profile) keeps its members in the given order, at the end.
    static QStringList of(const Profile& profile, QStringList names);
};

} // namespace opentop
