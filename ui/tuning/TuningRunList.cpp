#include "ui/tuning/TuningRunList.h"

#include <QHeaderView>
#include <QLocale>
#include <QPixmap>

namespace opentop {

TuningRunList::TuningRunList(QWidget* parent)
    : QTreeWidget(parent)
{
    setObjectName(QStringLiteral("tuningRuns"));
    setColumnCount(2);
    setHeaderLabels({tr("Run"), tr("Gains")});
    setRootIsDecorated(false);
    setUniformRowHeights(true);
    header()->setStretchLastSection(true);
    header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    connect(this, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem* item, int column) {
        if (column == 0)
            emit visibilityChanged(item->data(0, Qt::UserRole).toInt(),
                                   item->checkState(0) == Qt::Checked);
    });
    connect(this, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
        emit runSelected(item ? item->data(0, Qt::UserRole).toInt() : -1);
    });
}

QTreeWidgetItem* TuningRunList::itemOf(int id) const
{
    for (int i = 0; i < topLevelItemCount(); ++i) {
        if (topLevelItem(i)->data(0, Qt::UserRole).toInt() == id)
            return topLevelItem(i);
    }
    return nullptr;
}

void TuningRunList::fill(QTreeWidgetItem* item, const TuningRun& run)
{
    QPixmap swatch(14, 14);
    swatch.fill(run.color);
    item->setIcon(0, QIcon(swatch));
    item->setText(0, run.live ? tr("%1 (recording)").arg(run.title) : run.title);
    const QLocale locale;
    item->setText(1, tr("P %1 · I %2 · D %3")
                         .arg(locale.toString(run.gains.p, 'g', 4),
                              locale.toString(run.gains.i, 'g', 4),
                              locale.toString(run.gains.d, 'g', 4)));
    item->setToolTip(1, run.gains.toString());
    item->setCheckState(0, run.visible ? Qt::Checked : Qt::Unchecked);
}

void TuningRunList::addRun(const TuningRun& run)
{
    const QSignalBlocker block(this);
    auto* item = new QTreeWidgetItem(this);
    item->setData(0, Qt::UserRole, run.id);
    item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
    fill(item, run);
    setCurrentItem(item);
    scrollToItem(item);
}

void TuningRunList::updateRun(const TuningRun& run)
{
    const QSignalBlocker block(this);
    if (QTreeWidgetItem* item = itemOf(run.id))
        fill(item, run);
}

void TuningRunList::removeRun(int id)
{
    delete itemOf(id);
}

int TuningRunList::selectedRun() const
{
    return currentItem() ? currentItem()->data(0, Qt::UserRole).toInt() : -1;
}

void TuningRunList::selectRun(int id)
{
    if (QTreeWidgetItem* item = itemOf(id))
        setCurrentItem(item);
}

} // namespace opentop
