#include "cli/ScanDrives.h"

#include "cli/CliContext.h"
#include "model/profile/ProfileRegistry.h"

#include <QCoreApplication>

namespace opentop {

namespace {

// Part of the scan's output: its messages keep the scan's context (and translations).
QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::ScanDrives", text);
}

} // namespace

void ScanDrives::complete(CliContext& context, QVector<DeviceInfo>* devices)
{
    const ProfileRegistry& registry = ProfileRegistry::builtIn();
    for (DeviceInfo& info : *devices) {
        info.machineName = context.machineNames().value(info.slave); // `name`, or the window's
        const Profile* profile = registry.family(info.family);
        if (info.state != DeviceInfo::State::Present || !profile)
            continue;
        if (profile->variants.isEmpty()) {
            // One model per family: the device's own name says more than the family's title.
            if (!info.name.trimmed().isEmpty())
                info.model = info.name.trimmed();
            continue;
        }
        if (!info.variant.isEmpty())
            continue;
        info.variant = context.assignedVariant(info.slave, info.family);
        if (const ProfileVariant* v = profile->variant(info.variant)) {
            info.model = v->model;
            info.detail.clear();
        } else {
            const QString name =
                info.name.trimmed().isEmpty() ? profile->family.toUpper() : info.name.trimmed();
            info.model = tr("%1 — variant unknown").arg(name);
            info.detail = tr("the drive does not report its variant; give it with --variant "
                             "%1=VARIANT (%2)")
                              .arg(info.slave)
                              .arg([&] {
                                  QStringList ids;
                                  for (const ProfileVariant& pv : profile->variants)
                                      ids << pv.id;
                                  return ids.join(QStringLiteral(", "));
                              }());
        }
    }
}

} // namespace opentop
