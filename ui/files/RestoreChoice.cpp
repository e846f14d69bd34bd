#include "ui/files/RestoreChoice.h"

#include "model/bus/BusDrives.h"
#include "model/bus/DriveName.h"
#include "model/profile/ProfileRegistry.h"
#include "model/session/DeviceSession.h"

#include <QComboBox>
#include <QHeaderView>

namespace opentop {

namespace {

enum Column
{
    Setting,
    FileValue,
    Target
};

} // namespace

RestoreChoice::RestoreChoice(QWidget* parent)
    : QTreeWidget(parent)
{
    setColumnCount(3);
    setHeaderLabels({tr("Drive in file / setting"), tr("Value in file"), tr("Restore to")});
    header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    connect(this, &QTreeWidget::itemChanged, this, &RestoreChoice::changed);
}

void RestoreChoice::setFile(const BackupFile& file, BusDrives* drives)
{
    const QSignalBlocker block(this);
    clear();
    for (const BackupDevice& device : file.devices) {
        const Profile* profile = ProfileRegistry::builtIn().family(device.family);
        auto* top = new QTreeWidgetItem(this);
        top->setText(Setting, device.title());
        top->setData(Setting, Qt::UserRole, device.slave);
        top->setFlags(top->flags() | Qt::ItemIsUserCheckable | Qt::ItemIsAutoTristate);
        top->setCheckState(Setting, Qt::Checked);
        for (const BackupParameter& p : device.parameters) {
            const ParameterMeta* meta = profile ? profile->parameter(p.name) : nullptr;
            auto* item = new QTreeWidgetItem(top);
            item->setText(Setting,
                          meta ? QStringLiteral("%1 (%2)").arg(meta->label, p.name) : p.name);
            item->setData(Setting, Qt::UserRole, p.name);
            item->setText(FileValue, profile ? device.text(*profile, p.name) : QString());
            item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
            item->setCheckState(Setting, Qt::Checked);
        }
        auto* combo = new QComboBox;
        combo->addItem(tr("(do not restore)"), 0);
        if (drives) {
            for (int slave : drives->slaves()) {
                if (drives->session(slave))
                    combo->addItem(tr("Drive %1 (%2)")
                                       .arg(slave)
                                       .arg(DriveName::nameAndModel(drives->name(slave),
                                                                    drives->info(slave).model)),
                                   slave);
            }
        }
        combo->setCurrentIndex(std::max(0, combo->findData(device.slave)));
        setItemWidget(top, Target, combo);
        connect(combo, &QComboBox::currentIndexChanged, this, &RestoreChoice::changed);
    }
}

QTreeWidgetItem* RestoreChoice::driveItem(int fileSlave) const
{
    for (int i = 0; i < topLevelItemCount(); ++i) {
        if (topLevelItem(i)->data(Setting, Qt::UserRole).toInt() == fileSlave)
            return topLevelItem(i);
    }
    return nullptr;
}

void RestoreChoice::setTarget(int fileSlave, int busSlave)
{
    QTreeWidgetItem* top = driveItem(fileSlave);
    auto* combo = top ? qobject_cast<QComboBox*>(itemWidget(top, Target)) : nullptr;
    if (combo)
        combo->setCurrentIndex(std::max(0, combo->findData(busSlave)));
}

int RestoreChoice::target(int fileSlave) const
{
    QTreeWidgetItem* top = driveItem(fileSlave);
    auto* combo = top ? qobject_cast<QComboBox*>(itemWidget(top, Target)) : nullptr;
    return combo ? combo->currentData().toInt() : 0;
}

void RestoreChoice::setParameters(int fileSlave, const QStringList& names)
{
    QTreeWidgetItem* top = driveItem(fileSlave);
    if (!top)
        return;
    for (int i = 0; i < top->childCount(); ++i) {
        QTreeWidgetItem* child = top->child(i);
        child->setCheckState(Setting, names.contains(child->data(Setting, Qt::UserRole).toString())
                                          ? Qt::Checked
                                          : Qt::Unchecked);
    }
}

QVector<RestoreChoice::Job> RestoreChoice::jobs(const BackupFile& file, BusDrives* drives,
                                                QString* error) const
{
    QVector<Job> result;
    for (int i = 0; i < topLevelItemCount(); ++i) {
        QTreeWidgetItem* top = topLevelItem(i);
        const BackupDevice* device = file.device(top->data(Setting, Qt::UserRole).toInt());
        const int busSlave = device ? target(device->slave) : 0;
        if (busSlave == 0 || top->checkState(Setting) == Qt::Unchecked)
            continue;
        for (const Job& j : result) {
            if (j.busSlave == busSlave) {
                *error = tr("Two drives of the file would be restored to drive %1.").arg(busSlave);
                return {};
            }
        }
        if (!drives || !drives->session(busSlave)) {
            *error = tr("Drive %1 is not on the bus (or not identified).").arg(busSlave);
            return {};
        }
        Job job{busSlave, *device};
        job.device.parameters.clear();
        for (int c = 0; c < top->childCount(); ++c) {
            if (top->child(c)->checkState(Setting) == Qt::Checked)
                job.device.parameters << device->parameters.at(c);
        }
        result << job;
    }
    if (result.isEmpty() && error->isEmpty())
        *error = tr("Nothing chosen: tick at least one setting of a drive with a target.");
    return result;
}

} // namespace opentop
