#include "model/bus/VariantNeed.h"

#include "model/bus/BusDrives.h"
#include "model/profile/ProfileRegistry.h"
#include "model/profile/ValueCodec.h"
#include "model/session/DeviceSession.h"

#include <QMap>

namespace opentop {

namespace {

// "SPno2 speed", "SPno2 speed and 6 more": a list people read.
QString someLabels(const QStringList& labels)
{
    if (labels.size() <= 2)
        return labels.join(QStringLiteral(", "));
    return VariantNeed::tr("%1 and %2 more").arg(labels.first()).arg(labels.size() - 1);
}

} // namespace

bool VariantNeed::needed(const BusDrives& drives, int slave, Purpose purpose,
                         const QStringList& parameters)
{
    const DeviceSession* session = drives.session(slave);
    if (!session || !session->variant().isEmpty() || drives.variantDeclined(slave))
        return false;
    const Profile& profile = session->profile();
    if (profile.variants.size() < 2)
        return false;
    if (purpose != Purpose::Write)
        return true;
    const QStringList depend = dependent(profile);
    for (const QString& p : parameters) {
        if (depend.contains(p))
            return true;
    }
    return false;
}

QStringList VariantNeed::dependent(const Profile& profile)
{
    QStringList names;
    for (const ParameterMeta& m : profile.parameters) {
        for (const ValueCondition& c : m.conditions) {
            if (!c.variant.isEmpty() && !names.contains(m.name))
                names << m.name;
        }
    }
    return names;
}

QString VariantNeed::whatItChanges(const Profile& profile)
{
    QStringList lines;
    for (const ProfileVariant& v : profile.variants)
        lines << QStringLiteral("• ") + (v.label.isEmpty() ? v.model : v.label);
    // Settings whose allowed values differ, grouped by what they allow on each variant.
    QMap<QString, QStringList> byAllowed;
    QStringList order;
    for (const QString& name : dependent(profile)) {
        const ParameterMeta* m = profile.parameter(name);
        QStringList each;
        for (const ProfileVariant& v : profile.variants) {
            ValueContext context;
            context.variant = v.id;
            each << tr("%1: %2").arg(v.model, ValueCodec::allowedText(*m, context));
        }
        const QString allowed = each.join(QStringLiteral("; "));
        if (!byAllowed.contains(allowed))
            order << allowed;
        byAllowed[allowed] << m->label;
    }
    for (const QString& allowed : order)
        lines << tr("Allowed %1 — %2").arg(someLabels(byAllowed.value(allowed)), allowed);
    return lines.join(QLatin1Char('\n'));
}

QString VariantNeed::question(const BusDrives& drives, int slave, Purpose purpose,
                              const QString& remembered)
{
    const DeviceSession* session = drives.session(slave);
    if (!session)
        return QString();
    const Profile& profile = session->profile();
    QStringList models;
    for (const ProfileVariant& v : profile.variants)
        models << v.model;
    QString why;
    switch (purpose) {
    case Purpose::Write:
        why = tr("The allowed values of the settings you are changing depend on it.");
        break;
    case Purpose::Backup:
        why = tr("The backup file records it, and a restore checks the values against it.");
        break;
    case Purpose::Start:
        why = tr("The speeds the motor may run at depend on it.");
        break;
    }
    QString text =
        tr("Which drive is %1? It reports only \"%2\", not whether it is a %3.")
            .arg(drives.label(slave), profile.family.toUpper(), models.join(tr(" or "))) +
        QLatin1Char(' ') + why + QStringLiteral("\n\n") + whatItChanges(profile) +
        QStringLiteral("\n\n") +
        tr("Read it on the drive's rating plate. It is kept for this bus and asked "
           "once; without it every value must suit all of them.");
    if (const ProfileVariant* last = profile.variant(remembered))
        text +=
            QStringLiteral("\n\n") + tr("Last time on this bus it was set as %1.").arg(last->model);
    return text;
}

} // namespace opentop
