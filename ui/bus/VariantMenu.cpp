#include "ui/bus/VariantMenu.h"

#include "model/bus/BusDrives.h"
#include "model/profile/ProfileRegistry.h"

#include <QActionGroup>
#include <QCoreApplication>
#include <QMenu>

namespace opentop {

void VariantMenu::add(QMenu* menu, BusDrives* drives, const QVector<int>& slaves)
{
    const DeviceInfo first = drives->info(slaves.first());
    const Profile* profile = ProfileRegistry::builtIn().family(first.family);
    // A variant applies to the selected drives of the same family.
    QVector<int> sameFamily;
    for (int s : slaves) {
        if (drives->info(s).family == first.family &&
            drives->info(s).state == DeviceInfo::State::Present)
            sameFamily << s;
    }
    if (!profile || profile->variants.size() < 2 || sameFamily.isEmpty())
        return;
    // The bus list's text, as before it moved here.
    QMenu* variants = menu->addMenu(QCoreApplication::translate("opentop::BusPanel", "&Variant"));
    variants->setToolTipsVisible(true);
    auto* group = new QActionGroup(variants);
    for (const ProfileVariant& v : profile->variants) {
        QAction* a = variants->addAction(v.model);
        a->setObjectName(v.id);
        a->setToolTip(v.label);
        a->setCheckable(true);
        a->setChecked(first.variant == v.id);
        group->addAction(a);
        QObject::connect(a, &QAction::triggered, drives, [drives, sameFamily, id = v.id] {
            for (int s : sameFamily)
                drives->setVariant(s, id);
        });
    }
}

} // namespace opentop
