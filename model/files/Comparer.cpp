#include "model/files/Comparer.h"

#include "model/files/BackupReader.h"
#include "model/profile/ValueCodec.h"

#include <algorithm>

namespace opentop {

Comparer::Result Comparer::compare(const Profile& profile, const BackupDevice& a,
                                   const BackupDevice& b)
{
    Result result;
    if (a.family != b.family || a.family != profile.family) {
        result.refusal = tr("nothing to compare: %1 is a %2 drive, %3 a %4 drive")
                             .arg(a.title(), a.family, b.title(), b.family);
        return result;
    }
    if (!a.variant.isEmpty() && !b.variant.isEmpty() && a.variant != b.variant)
        result.notes << tr("the variants differ: %1 and %2").arg(a.variant, b.variant);
    for (const ParameterMeta& meta : profile.parameters) {
        const BackupParameter* pa = a.parameter(meta.name);
        const BackupParameter* pb = b.parameter(meta.name);
        if (!pa && !pb)
            continue;
        if (pa && pb) {
            ++result.compared;
            if (pa->registers == pb->registers)
                continue;
        }
        Difference d;
        d.parameter = meta.name;
        d.label = meta.label;
        if (pa) {
            d.a = a.text(profile, meta.name);
            d.aRegisters = pa->registers;
        }
        if (pb) {
            d.b = b.text(profile, meta.name);
            d.bRegisters = pb->registers;
        }
        result.differences << d;
    }
    return result;
}

BackupDevice Comparer::factoryDefaults(const Profile& profile, const QString& variant,
                                       QStringList* undocumented)
{
    BackupDevice defaults;
    defaults.family = profile.family;
    defaults.variant = variant;
    const ProfileVariant* v = profile.variant(variant);
    defaults.model = v ? v->model : profile.name;
    defaults.name = tr("factory defaults");
    // Two passes: first the defaults that depend on nothing, then the ones whose allowed set
    // and default follow another parameter's (default) value.
    for (int pass = 0; pass < 2; ++pass) {
        const ValueContext context = defaults.context(profile);
        for (const QString& name : BackupReader::settingNames(profile)) {
            const ParameterMeta& meta = *profile.parameter(name);
            if (meta.dependsOnParameter() != (pass == 1))
                continue;
            const ValueSpec& spec = meta.specFor(context);
            QVector<quint16> registers;
            if (spec.defaultRaw)
                registers = ValueCodec::rawToRegisters(meta, *spec.defaultRaw);
            else if (meta.type == DataType::String && !spec.defaultText.isEmpty())
                registers = ValueCodec::encodeText(meta, spec.defaultText, context).registers;
            if (registers.isEmpty()) {
                if (undocumented)
                    *undocumented << name;
                continue;
            }
            defaults.parameters << BackupParameter{name, registers};
        }
    }
    // Back into profile order, as every other parameter set.
    const QStringList order = BackupReader::settingNames(profile);
    std::sort(defaults.parameters.begin(), defaults.parameters.end(),
              [&order](const BackupParameter& x, const BackupParameter& y) {
                  return order.indexOf(x.name) < order.indexOf(y.name);
              });
    if (undocumented) {
        std::sort(undocumented->begin(), undocumented->end(),
                  [&order](const QString& x, const QString& y) {
                      return order.indexOf(x) < order.indexOf(y);
                  });
    }
    return defaults;
}

Comparer::Result Comparer::compareWithDefaults(const Profile& profile, const BackupDevice& a)
{
    QStringList undocumented;
    const BackupDevice defaults = factoryDefaults(profile, a.variant, &undocumented);
    BackupDevice held = a;
    // Parameters without a documented default are listed, never compared.
    held.parameters.erase(
        std::remove_if(held.parameters.begin(), held.parameters.end(),
                       [&](const BackupParameter& p) { return undocumented.contains(p.name); }),
        held.parameters.end());
    Result result = compare(profile, held, defaults);
    for (const QString& name : undocumented) {
        if (a.parameter(name))
            result.noDefault << name;
    }
    return result;
}

} // namespace opentop
