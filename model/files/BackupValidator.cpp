#include "model/files/BackupValidator.h"

#include "model/profile/ValueCodec.h"

#include <QSet>

namespace opentop {

QStringList BackupValidator::checkStructure(const Profile& profile, const BackupDevice& device)
{
    QStringList problems;
    QSet<QString> seen;
    for (const BackupParameter& p : device.parameters) {
        const ParameterMeta* meta = profile.parameter(p.name);
        if (!meta) {
            problems << tr("unknown parameter \"%1\": the %2 profile has no such setting")
                            .arg(p.name, profile.family);
            continue;
        }
        if (!meta->backup) {
            problems << tr("\"%1\" is not a setting that backups hold").arg(p.name);
            continue;
        }
        if (seen.contains(p.name))
            problems << tr("\"%1\" appears twice").arg(p.name);
        seen.insert(p.name);
        if (p.registers.size() != meta->registerCount)
            problems << tr("%1: %2 registers, but the parameter has %3")
                            .arg(p.name)
                            .arg(p.registers.size())
                            .arg(meta->registerCount);
    }
    return problems;
}

QStringList BackupValidator::checkValues(const Profile& profile, const BackupDevice& device,
                                         const QString& variant, UnknownVariant unknown)
{
    QStringList problems;
    ValueContext context = device.context(profile);
    context.variant = variant;
    if (variant.isEmpty() && unknown == UnknownVariant::AllMustFit) {
        for (const ProfileVariant& v : profile.variants)
            context.possibleVariants << v.id;
    }
    for (const BackupParameter& p : device.parameters) {
        const ParameterMeta* meta = profile.parameter(p.name);
        if (!meta || p.registers.size() != meta->registerCount)
            continue; // a structure problem, reported by checkStructure
        bool resolvable = true;
        for (const QString& controlling : meta->controllingParameters()) {
            if (!device.parameter(controlling)) {
                problems << tr("%1: its allowed values depend on %2, which the file does not hold")
                                .arg(p.name, controlling);
                resolvable = false;
            }
        }
        if (!resolvable)
            continue;
        const double raw = ValueCodec::registersToRaw(*meta, p.registers);
        QString error = ValueCodec::checkRaw(*meta, raw, context);
        if (!error.isEmpty() && variant.isEmpty() && unknown == UnknownVariant::AnyMayFit) {
            for (const ProfileVariant& v : profile.variants) {
                ValueContext one = context;
                one.variant = v.id;
                if (ValueCodec::checkRaw(*meta, raw, one).isEmpty()) {
                    error.clear();
                    break;
                }
            }
        }
        if (!error.isEmpty())
            problems << error;
    }
    return problems;
}

} // namespace opentop
