#include "model/files/BackupDevice.h"

#include "model/bus/DriveName.h"
#include "model/profile/ValueCodec.h"

#include <QCoreApplication>
#include <QHash>

namespace opentop {

const BackupParameter* BackupDevice::parameter(const QString& parameterName) const
{
    for (const BackupParameter& p : parameters) {
        if (p.name == parameterName)
            return &p;
    }
    return nullptr;
}

QStringList BackupDevice::parameterNames() const
{
    QStringList names;
    for (const BackupParameter& p : parameters)
        names << p.name;
    return names;
}

ValueContext BackupDevice::context(const Profile& profile) const
{
    ValueContext c;
    c.variant = variant;
    // A copy of the values, so that the context stays valid when this device is gone. The
    // profile is one of the long-lived registry's.
    QHash<QString, QVector<quint16>> values;
    for (const BackupParameter& p : parameters)
        values.insert(p.name, p.registers);
    const Profile* source = &profile;
    c.parameterRaw = [values, source](const QString& parameterName) -> std::optional<qint64> {
        const ParameterMeta* meta = source->parameter(parameterName);
        const auto it = values.constFind(parameterName);
        if (!meta || it == values.cend() || it->size() != meta->registerCount)
            return std::nullopt;
        return qint64(ValueCodec::registersToRaw(*meta, *it));
    };
    return c;
}

ParamValue BackupDevice::value(const Profile& profile, const QString& parameterName) const
{
    const ParameterMeta* meta = profile.parameter(parameterName);
    const BackupParameter* p = parameter(parameterName);
    if (!meta || !p)
        return {};
    return ValueCodec::decode(*meta, p->registers, context(profile));
}

QString BackupDevice::text(const Profile& profile, const QString& parameterName) const
{
    const ParameterMeta* meta = profile.parameter(parameterName);
    if (!meta || !parameter(parameterName))
        return QString();
    return ValueCodec::format(*meta, value(profile, parameterName), context(profile));
}

QString BackupDevice::unit(const Profile& profile, const QString& parameterName) const
{
    const ParameterMeta* meta = profile.parameter(parameterName);
    return meta ? meta->specFor(context(profile)).unit : QString();
}

QString BackupDevice::title() const
{
    const QString what = model.isEmpty() ? family : model;
    if (slave <= 0)
        return what;
    return DriveName::withModel(slave, machineName, what);
}

} // namespace opentop
