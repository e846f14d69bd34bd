#include "model/profile/WriteOrder.h"

#include "model/profile/Profile.h"

#include <algorithm>

namespace opentop {

QStringList WriteOrder::of(const Profile& profile, QStringList names)
{
    // Kahn's algorithm, taking the first ready name each time: stable, and correct for chains
    // (a comparison sort on direct dependencies is not an ordering when they chain).
    QStringList ordered;
    while (!names.isEmpty()) {
        const auto ready = std::find_if(names.begin(), names.end(), [&](const QString& name) {
            const ParameterMeta* meta = profile.parameter(name);
            const QStringList needs = meta ? meta->controllingParameters() : QStringList();
            return std::none_of(needs.begin(), needs.end(),
                                [&](const QString& n) { return n != name && names.contains(n); });
        });
        if (ready == names.end()) {
            ordered += names;
            break;
        }
        ordered << *ready;
        names.erase(ready);
    }
    return ordered;
}

} // namespace opentop
