#include "ui/main/BusDocks.h"

#include "model/bus/BusDrives.h"
#include "transport/TrafficLog.h"
#include "ui/bus/BusListModel.h"
#include "ui/bus/BusOverview.h"
#include "ui/bus/BusPanel.h"
#include "ui/groups/GroupsView.h"
#include "ui/traffic/TrafficLogView.h"
#include "ui/trends/TrendPanel.h"

#include <QDockWidget>
#include <QLabel>
#include <QMainWindow>
#include <QScreen>
#include <QScrollArea>
#include <QTableView>
#include <QTimer>
#include <algorithm>

namespace opentop {

BusDocks::BusDocks(QMainWindow* window, TrafficLog* log)
    : QObject(window)
    , m_window(window)
{
    // Every frame, decoded with parameter names, in a dock that can be shown or hidden.
    auto* trafficDock = new QDockWidget(tr("Traffic log"), window);
    trafficDock->setObjectName(QStringLiteral("trafficDock"));
    trafficDock->setWidget(new TrafficLogView(log, trafficDock));
    window->addDockWidget(Qt::BottomDockWidgetArea, trafficDock);
    trafficDock->hide();
    // Live views of the whole bus; their contents are made per connection.
    for (const auto& [name, title] :
         {std::pair(QStringLiteral("overviewDock"), tr("Bus overview")),
          std::pair(QStringLiteral("trendDock"), tr("Trends")),
          std::pair(QStringLiteral("groupsDock"), tr("Communication groups"))}) {
        auto* d = new QDockWidget(title, window);
        d->setObjectName(name);
        d->setWidget(new QLabel(tr("Not connected"), d));
        window->addDockWidget(Qt::BottomDockWidgetArea, d);
        d->hide();
    }
    // The bottom docks share one place as tabs: side by side they would not fit a laptop's
    // width, and each still has the full width for its columns.
    window->tabifyDockWidget(trafficDock, dock(QStringLiteral("overviewDock")));
    window->tabifyDockWidget(trafficDock, dock(QStringLiteral("trendDock")));
    window->tabifyDockWidget(trafficDock, dock(QStringLiteral("groupsDock")));
    // The first time the bottom opens it takes a fifth of the window: the page above keeps
    // its live values in sight on a laptop. The user's own dragging is kept after that.
    for (QDockWidget* d : window->findChildren<QDockWidget*>()) {
        connect(d, &QDockWidget::visibilityChanged, this, [this, d](bool visible) {
            if (!visible || m_bottomSized || d->isFloating() ||
                m_window->dockWidgetArea(d) != Qt::BottomDockWidgetArea)
                return;
            m_bottomSized = true;
            QTimer::singleShot(0, d, [window = m_window, d] {
                window->resizeDocks({d}, {firstHeight(window)}, Qt::Vertical);
            });
        });
    }
}

int BusDocks::firstHeight(QMainWindow* window)
{
    // Never below what a dock's contents need: their minimum, and what their wrapped texts
    // need more at the window's width (longer in some languages).
    int needed = 0;
    for (QDockWidget* d : window->findChildren<QDockWidget*>()) {
        if (window->dockWidgetArea(d) != Qt::BottomDockWidgetArea || !d->widget())
            continue;
        int wrapped = 0;
        for (QLabel* label : d->widget()->findChildren<QLabel*>()) {
            if (label->wordWrap() && !label->text().isEmpty())
                wrapped += std::max(0, label->heightForWidth(window->width() - 40) -
                                           label->minimumSizeHint().height());
        }
        needed = std::max(needed, d->minimumSizeHint().height() + wrapped);
    }
    return std::max(std::clamp(window->height() / 5, 140, 320), needed);
}

QDockWidget* BusDocks::dock(const QString& name) const
{
    return m_window->findChild<QDockWidget*>(name);
}

void BusDocks::fill(BusDrives* drives, MonitorHub* hub, BusGroupTracker* groups, BusPanel* panel)
{
    m_overview = new BusOverview(drives, hub, dock(QStringLiteral("overviewDock")));
    connect(m_overview, &BusOverview::driveActivated, m_window,
            [panel](int slave) { panel->view()->selectRow(panel->model()->rowOf(slave)); });
    m_trends = new TrendPanel(hub, dock(QStringLiteral("trendDock")));
    m_groupsView = new GroupsView(groups, dock(QStringLiteral("groupsDock")));
    replace(QStringLiteral("overviewDock"), m_overview);
    // The trends scroll in their dock rather than holding the window taller than a laptop's
    // screen when it shares the bottom with the other docks.
    auto* trendScroll = new QScrollArea(dock(QStringLiteral("trendDock")));
    trendScroll->setWidgetResizable(true);
    trendScroll->setFrameShape(QFrame::NoFrame);
    trendScroll->setWidget(m_trends);
    replace(QStringLiteral("trendDock"), trendScroll);
    replace(QStringLiteral("groupsDock"), m_groupsView);
}

void BusDocks::clear()
{
    for (const QString& name : {QStringLiteral("overviewDock"), QStringLiteral("trendDock"),
                                QStringLiteral("groupsDock")})
        replace(name, new QLabel(tr("Not connected"), dock(name)));
    m_overview = nullptr;
    m_trends = nullptr;
    m_groupsView = nullptr;
}

void BusDocks::replace(const QString& name, QWidget* widget)
{
    QWidget* old = dock(name)->widget();
    dock(name)->setWidget(widget);
    delete old;
}

void BusDocks::monitorAll(const QVector<int>& slaves)
{
    QDockWidget* overview = dock(QStringLiteral("overviewDock"));
    overview->show();
    overview->raise();
    // A window of its own: as a tab behind the overview it would be neither seen nor drawn,
    // and beside it the window would no longer fit a laptop's screen.
    QDockWidget* trends = dock(QStringLiteral("trendDock"));
    trends->setFloating(true);
    trends->show();
    const QRect screen = m_window->screen()->availableGeometry();
    trends->resize(std::min(900, screen.width()), std::min(480, screen.height()));
    trends->move(screen.right() - trends->frameGeometry().width() + 1,
                 screen.bottom() - trends->frameGeometry().height() + 1);
    m_trends->showDrives(slaves);
}

} // namespace opentop
