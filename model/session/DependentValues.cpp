#include "model/session/DependentValues.h"

#include "model/profile/ValueCodec.h"

namespace opentop {

QStringList DependentValues::of(const Profile& profile, const ParameterMeta& meta)
{
    QStringList names;
    // Only values a drive holds: a write-only command (the DC controller's speed command, whose
    // range follows the speed mode) has nothing a mode change could leave invalid, and could
    // not be read to check.
    for (const ParameterMeta& p : profile.parameters) {
        if (p.isWritable() && p.isReadable() && p.controllingParameters().contains(meta.name))
            names << p.name;
    }
    return names;
}

QString DependentValues::problem(const Profile& profile, const ParameterMeta& meta, qint64 raw,
                                 const ValueContext& device, const QStringList& companions)
{
    // The drive as it would be right after this write.
    ValueContext after = device;
    const auto before = device.parameterRaw;
    after.parameterRaw = [before, &meta, raw](const QString& name) -> std::optional<qint64> {
        if (name == meta.name)
            return raw;
        return before ? before(name) : std::nullopt;
    };
    QStringList invalid;
    QStringList unknown;
    for (const QString& name : of(profile, meta)) {
        if (companions.contains(name))
            continue;
        const ParameterMeta* dependent = profile.parameter(name);
        const std::optional<qint64> current = device.rawOf(name);
        if (!current) {
            unknown << dependent->label;
            continue;
        }
        if (!ValueCodec::checkRaw(*dependent, double(*current), after).isEmpty()) {
            const ParamValue value = ValueCodec::decode(
                *dependent, ValueCodec::rawToRegisters(*dependent, double(*current)), device);
            invalid << tr("%1 (%2)").arg(dependent->label,
                                         ValueCodec::format(*dependent, value, device));
        }
    }
    const QString newValue = ValueCodec::format(
        meta, ValueCodec::decode(meta, ValueCodec::rawToRegisters(meta, double(raw)), after),
        after);
    if (!invalid.isEmpty())
        return tr("%1 = %2 would leave %3 without a valid value, because what they allow depends "
                  "on it. Choose new values for them and write them together with it.")
            .arg(meta.label, newValue, invalid.join(QStringLiteral(", ")));
    if (!unknown.isEmpty())
        return tr("%1 cannot be checked: the values of %2 depend on it and could not be read")
            .arg(meta.label, unknown.join(QStringLiteral(", ")));
    return {};
}

} // namespace opentop
