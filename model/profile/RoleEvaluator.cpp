#include "model/profile/RoleEvaluator.h"

#include "model/profile/ValueCodec.h"

namespace opentop {

namespace {

const EnumOption* optionFor(const ValueSpec& spec, qint64 raw)
{
    for (const EnumOption& o : spec.options) {
        if (o.value == raw)
            return &o;
    }
    return nullptr;
}

} // namespace

const ParameterMeta* RoleEvaluator::parameter(const Profile& profile, const QString& role)
{
    const ProfileRole* r = profile.role(role);
    return r && !r->parameter.isEmpty() ? profile.parameter(r->parameter) : nullptr;
}

std::optional<bool> RoleEvaluator::flag(const Profile& profile, const QString& role,
                                        const RawLookup& raw)
{
    const ProfileRole* r = profile.role(role);
    const ParameterMeta* meta = parameter(profile, role);
    if (!r || !meta)
        return std::nullopt;
    const std::optional<double> value = raw(meta->name);
    if (!value)
        return std::nullopt;
    if (!r->field.isEmpty()) {
        const BitField* f = bitField(*meta, r->field);
        if (!f)
            return std::nullopt;
        return fieldValue(*f, *value) != 0;
    }
    return *value != 0;
}

std::optional<bool> RoleEvaluator::holds(const Profile& profile, const QString& role,
                                         const RawLookup& raw)
{
    const ProfileRole* r = profile.role(role);
    const ParameterMeta* meta = parameter(profile, role);
    if (!r || !meta || !r->value)
        return std::nullopt;
    const std::optional<double> value = raw(meta->name);
    if (!value)
        return std::nullopt;
    return qint64(*value) == *r->value;
}

const BitField* RoleEvaluator::bitField(const ParameterMeta& meta, const QString& field)
{
    for (const BitField& f : meta.bits) {
        if (f.name == field)
            return &f;
    }
    return nullptr;
}

qint64 RoleEvaluator::fieldValue(const BitField& field, double raw)
{
    const quint64 mask = (quint64(1) << field.width) - 1;
    return qint64((quint64(raw) >> field.bit) & mask);
}

QString RoleEvaluator::fieldText(const BitField& field, qint64 value)
{
    if (value >= 0 && value < field.values.size())
        return field.values.at(int(value));
    return QString::number(value);
}

QString RoleEvaluator::writeText(const ParameterMeta& meta, qint64 raw, const ValueContext& context)
{
    const ValueSpec& spec = meta.specFor(context);
    // Hexadecimal is a raw code to the codec, never mistaken for a label such as "1".
    if (optionFor(spec, raw) && spec.ranges.isEmpty() && raw >= 0)
        return QStringLiteral("0x%1").arg(raw, 0, 16);
    // Engineering units; exact for the 0 the stop roles use whatever the scale.
    return QString::number(double(raw) * spec.scale, 'g', 12);
}

QString RoleEvaluator::valueText(const ParameterMeta& meta, qint64 raw, const ValueContext& context)
{
    const ValueSpec& spec = meta.specFor(context);
    if (const EnumOption* o = optionFor(spec, raw))
        return QStringLiteral("%1 (%2)").arg(o->label).arg(raw);
    const QString number = ValueCodec::formatNumber(double(raw) * spec.scale, spec.decimals);
    return spec.unit.isEmpty() ? number : number + QLatin1Char(' ') + spec.unit;
}

QString RoleEvaluator::describeWrite(const ParameterMeta& meta, const QString& valueText,
                                     const ValueContext& context)
{
    return tr("%1 = %2 (%3, function %4)")
        .arg(context.nameFor(meta.name), valueText, meta.addressText())
        .arg(meta.writeFunction, 2, 10, QLatin1Char('0'));
}

} // namespace opentop
