#include "ui/trends/TrendDefaults.h"

#include "model/profile/Profile.h"
#include "model/profile/RoleEvaluator.h"

namespace opentop {

QVector<TrendSource> TrendDefaults::forDrive(const Profile& profile, int slave)
{
    QVector<TrendSource> sources;
    for (const char* role : {"currentSpeed", "targetSpeed", "load"}) {
        if (const ParameterMeta* m = RoleEvaluator::parameter(profile, QLatin1String(role)))
            sources << TrendSource{slave, m->name};
    }
    if (sources.size() > 1)
        return sources;
    const ProfileRole* monitor = profile.role(QStringLiteral("monitor"));
    for (const QString& name : monitor ? monitor->parameters : QStringList()) {
        const ParameterMeta* m = profile.parameter(name);
        const TrendSource source{slave, name};
        if (m && m->isNumeric() && m->spec.options.isEmpty() && !sources.contains(source) &&
            sources.size() < 3)
            sources << source;
    }
    return sources;
}

} // namespace opentop
