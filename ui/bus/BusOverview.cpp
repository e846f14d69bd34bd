#include "ui/bus/BusOverview.h"

#include "model/bus/BusDrives.h"
#include "model/monitor/MonitorHub.h"
#include "ui/bus/BusOverviewModel.h"

#include <QHeaderView>
#include <QLabel>
#include <QTableView>
#include <QVBoxLayout>

namespace opentop {

BusOverview::BusOverview(BusDrives* drives, MonitorHub* hub, QWidget* parent)
    : QWidget(parent)
    , m_drives(drives)
    , m_hub(hub)
    , m_model(new BusOverviewModel(drives, hub, this))
    , m_view(new QTableView(this))
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    m_view->setModel(m_model);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_view->verticalHeader()->hide();
    m_view->horizontalHeader()->setStretchLastSection(true);
    // Sized to the contents when drives come and go, not on every update (that measures every
    // cell's text each time).
    connect(m_model, &QAbstractItemModel::modelReset, m_view, &QTableView::resizeColumnsToContents);
    connect(m_model, &QAbstractItemModel::dataChanged, this, [this] {
        if (!m_sized && m_model->rowCount() > 0 && m_hub->latest(m_model->slaves().first())) {
            m_sized = true;
            m_view->resizeColumnsToContents();
        }
    });
    m_view->setToolTip(tr("Double-click a drive to open its pages."));
    layout->addWidget(m_view);
    connect(m_view, &QTableView::doubleClicked, this, [this](const QModelIndex& index) {
        if (index.isValid())
            emit driveActivated(m_model->slaves().value(index.row()));
    });
    // Drives found while the overview is open are monitored too.
    connect(drives, &BusDrives::driveChanged, this, [this] {
        if (m_watching)
            watchAll();
    });
}

void BusOverview::watchAll()
{
    for (int s : m_drives->slaves()) {
        if (m_drives->session(s))
            m_hub->watch(s, this);
    }
}

void BusOverview::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    m_watching = true;
    watchAll();
}

void BusOverview::hideEvent(QHideEvent* event)
{
    QWidget::hideEvent(event);
    m_watching = false;
    for (int s : m_drives->slaves())
        m_hub->unwatch(s, this);
}

} // namespace opentop
