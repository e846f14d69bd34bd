#include "model/profile/VariantProbe.h"

#include "model/profile/Profile.h"
#include "model/profile/ValueCodec.h"

#include <QJsonValue>

namespace opentop {

namespace {

// Whether any role names `name`: the registers that start, stop, select, command a speed or
// change communication are never a probe's.
bool roleParameter(const Profile& profile, const QString& name)
{
    for (auto it = profile.roles.cbegin(); it != profile.roles.cend(); ++it) {
        if (it->parameter == name || it->parameters.contains(name))
            return true;
    }
    return false;
}

} // namespace

std::optional<VariantProbe> VariantProbe::of(const Profile& profile)
{
    if (profile.variantProbe.isEmpty())
        return std::nullopt;
    QString error;
    return read(profile, profile.variantProbe, &error);
}

QString VariantProbe::check(const Profile& profile, const QJsonObject& section)
{
    if (section.isEmpty())
        return QString();
    QString error;
    return read(profile, section, &error) ? QString() : error;
}

std::optional<VariantProbe> VariantProbe::read(const Profile& profile, const QJsonObject& section,
                                               QString* error)
{
    auto fail = [error](const QString& why) {
        *error = QStringLiteral("variantProbe: ") + why;
        return std::nullopt;
    };
    for (auto it = section.begin(); it != section.end(); ++it) {
        if (it.key() != QLatin1String("parameter") && it.key() != QLatin1String("value") &&
            it.key() != QLatin1String("refusedCode") && it.key() != QLatin1String("why"))
            return fail(tr("unknown key \"%1\"").arg(it.key()));
    }
    VariantProbe probe;
    probe.parameter = section.value(QStringLiteral("parameter")).toString();
    const QJsonValue value = section.value(QStringLiteral("value"));
    const QJsonValue code = section.value(QStringLiteral("refusedCode"));
    if (probe.parameter.isEmpty() || !value.isDouble() || !code.isDouble())
        return fail(tr("needs \"parameter\", a number \"value\" and \"refusedCode\""));
    probe.value = value.toDouble();
    probe.refusedCode = code.toInt();
    const ParameterMeta* meta = profile.parameter(probe.parameter);
    if (!meta)
        return fail(tr("no parameter \"%1\"").arg(probe.parameter));
    // Never a register that moves a motor, resets, stores or changes communication.
    if (meta->kind != QLatin1String("setting") || !meta->safety.isEmpty() || !meta->isWritable() ||
        !meta->isReadable() || roleParameter(profile, probe.parameter))
        return fail(tr("%1 must be a readable, writable setting that no role names (never a "
                       "command or a motion register)")
                        .arg(probe.parameter));
    for (const ProfileVariant& v : profile.variants) {
        ValueContext context;
        context.variant = v.id;
        const ValueCodec::Encoded e = ValueCodec::encodeNumber(*meta, probe.value, context);
        (e.ok ? probe.accepting : probe.refusing) << v.id;
    }
    if (probe.accepting.isEmpty() || probe.refusing.isEmpty())
        return fail(tr("%1 = %2 must be allowed on some variants and refused on others")
                        .arg(probe.parameter)
                        .arg(probe.value));
    return probe;
}

QString VariantProbe::describe(const Profile& profile) const
{
    const ParameterMeta* meta = profile.parameter(parameter);
    if (!meta)
        return parameter;
    const QString unit = meta->spec.canonicalUnit;
    return QStringLiteral("%1 = %2%3")
        .arg(meta->canonicalLabel, ValueCodec::formatNumber(value, meta->spec.decimals),
             unit.isEmpty() ? QString() : QStringLiteral(" ") + unit);
}

} // namespace opentop
