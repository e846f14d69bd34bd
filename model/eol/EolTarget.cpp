#include "model/eol/EolTarget.h"

#include "model/eol/RecipeChecker.h"
#include "model/profile/Profile.h"
#include "model/profile/ValueCodec.h"

#include <algorithm>

namespace opentop {

std::optional<BackupDevice> EolTarget::build(const Profile& profile, const RecipePosition& position,
                                             const QString& variant,
                                             const QHash<QString, double>& unitValues,
                                             QString* error)
{
    // The same context the checker validated the recipe in: controlling values (control mode,
    // speed mode) are the recipe's own, not whatever the drive holds before it is written.
    const ValueContext context = RecipeChecker::contextOf(profile, position, variant);
    BackupDevice device;
    device.slave = position.machineNumber;
    device.family = profile.family;
    device.variant = variant;
    device.name = position.name;
    const auto fail = [&](const QString& name, const QString& why) {
        if (error)
            *error = tr("%1: %2").arg(RecipeChecker::labelOf(profile, name), why);
        return std::nullopt;
    };
    // The codec's messages name the setting already (the context's display names).
    const auto refused = [&](const QString& why) {
        if (error)
            *error = why;
        return std::nullopt;
    };
    for (const RecipeSetting& s : position.settings) {
        const ParameterMeta* meta = profile.parameter(s.name);
        if (!meta)
            return fail(s.name, tr("not a parameter of %1").arg(profile.name));
        const ValueCodec::Encoded e =
            s.value.isDouble() ? ValueCodec::encodeNumber(*meta, s.value.toDouble(), context)
                               : ValueCodec::encodeText(*meta, s.value.toString(), context);
        if (!e.ok)
            return refused(e.error);
        device.parameters.append({s.name, e.registers});
    }
    for (const RecipeUnitValue& u : position.unitValues) {
        const ParameterMeta* meta = profile.parameter(u.name);
        if (!meta)
            return fail(u.name, tr("not a parameter of %1").arg(profile.name));
        if (!unitValues.contains(u.name))
            return fail(u.name, tr("this unit's value is missing"));
        const double value = unitValues.value(u.name);
        if (value < u.min || value > u.max)
            return fail(u.name, tr("%1 is outside this product's range %2–%3 %4")
                                    .arg(value)
                                    .arg(u.min)
                                    .arg(u.max)
                                    .arg(meta->specFor(context).canonicalUnit)
                                    .trimmed());
        const ValueCodec::Encoded e = ValueCodec::encodeNumber(*meta, value, context);
        if (!e.ok)
            return refused(e.error);
        device.parameters.append({u.name, e.registers});
    }
    // Profile order, as a backup holds them (metadata lives in one vector, so addresses order
    // like indices); the restore plan orders the writes.
    std::stable_sort(device.parameters.begin(), device.parameters.end(),
                     [&profile](const BackupParameter& a, const BackupParameter& b) {
                         return profile.parameter(a.name) < profile.parameter(b.name);
                     });
    return device;
}

} // namespace opentop
