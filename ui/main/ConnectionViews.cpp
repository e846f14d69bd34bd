#include "ui/main/ConnectionViews.h"

#include "model/bus/BusDrives.h"
#include "model/bus/BusGroupTracker.h"
#include "model/monitor/MonitorHub.h"
#include "model/station/EolStation.h"
#include "ui/alarms/AlarmBanner.h"
#include "ui/alarms/AlarmsPage.h"
#include "ui/bus/BusPanel.h"
#include "ui/bus/BusRecallBar.h"
#include "ui/eol/ProductionMode.h"
#include "ui/main/BusDocks.h"
#include "ui/main/DrivePages.h"
#include "ui/main/MainWindow.h"
#include "ui/run/StopAllButton.h"
#include "ui/workspace/DriveWorkspace.h"

#include <QAction>
#include <QSplitter>
#include <QStatusBar>
#include <QToolBar>
#include <QVBoxLayout>

namespace opentop {

ConnectionViews::ConnectionViews(MainWindow* window, QWidget* central, QSplitter* splitter,
                                 BusDocks* docks, DrivePages* pages)
    : QObject(window)
    , m_window(window)
    , m_central(central)
    , m_splitter(splitter)
    , m_docks(docks)
    , m_pages(pages)
{
}

void ConnectionViews::make(BusDrives* drives, DriveStatusPoller* poller, BusGroupTracker* groups,
                           QToolBar* toolbar, const ConnectionSettings& settings, bool offerRecall)
{
    m_panel = new BusPanel(drives, poller, m_splitter);
    m_hub = new MonitorHub(drives, m_window);
    m_docks->fill(drives, m_hub, groups, m_panel);
    // STOP ALL is always on the toolbar and on the keyboard (StopAllButton::shortcuts()).
    m_toolbar = toolbar;
    m_stopAll = new StopAllButton(drives, toolbar);
    m_stopAllAction = toolbar->addWidget(m_stopAll);
    // The station's recipe knows its machine numbers: STOP ALL checks them, scanned or not.
    m_stopAll->setExpectedDrives([window = m_window] {
        QVector<QPair<int, QString>> expected;
        const EolStation* station =
            window->production() ? window->production()->station() : nullptr;
        if (station && station->hasRecipe())
            for (const RecipePosition& p : station->recipe().positions)
                expected.append({p.machineNumber, p.family});
        return expected;
    });
    // STOP ALL may end in alarms (or clear a run that hid one): the open page reads again.
    connect(m_stopAll, &StopAllButton::finished, m_window, [window = m_window] {
        if (AlarmsPage* page = window->alarmsPage())
            page->refresh();
    });
    m_banner = new AlarmBanner(poller, m_central);
    auto* column = static_cast<QVBoxLayout*>(m_central->layout());
    column->insertWidget(0, m_banner);
    connect(m_banner, &AlarmBanner::showAlarms, m_window, &MainWindow::showAlarmsOf);
    // The drives last seen here, offered back (the window identifies them).
    m_recall = new BusRecallBar(drives, settings, offerRecall, m_central);
    column->insertWidget(column->indexOf(m_splitter), m_recall);
    connect(m_recall, &BusRecallBar::scanRequested, m_window, [this] {
        if (m_panel && m_window->isConnected() && !m_panel->isScanning())
            m_panel->startScan(1, 247);
    });
    // The header names the model once the variant is known (identified or set by hand).
    connect(drives, &BusDrives::driveChanged, m_pages, &DrivePages::retitle);
    // A group setup that is wrong is said where the engineer looks, not only in its view.
    connect(groups, &BusGroupTracker::groupsChanged, m_window, [window = m_window, groups] {
        const QVector<BusGroups::Problem> problems = groups->groups().problems();
        if (!problems.isEmpty())
            window->statusBar()->showMessage(
                tr("Communication groups: %1 (Bus › Communication groups)")
                    .arg(BusGroups::describe(problems.first())),
                15000);
    });
    // The placeholder of the first connection; on a reconnection the old panel is gone and
    // the first widget is the workspace, which stays.
    if (m_splitter->widget(0) != m_window->workspace())
        delete m_splitter->widget(0);
    m_splitter->insertWidget(0, m_panel);
    m_splitter->setStretchFactor(0, 0);
    connect(m_panel, &BusPanel::selectionChanged, m_pages, &DrivePages::showDrive);
}

void ConnectionViews::clear()
{
    delete m_recall; // before the drives: it remembers what is left of them
    m_recall = nullptr;
    m_docks->clear();
    delete m_hub; // before the drives: its monitors use their sessions
    m_hub = nullptr;
    if (m_stopAllAction) {
        m_toolbar->removeAction(m_stopAllAction);
        m_stopAllAction = nullptr;
    }
    delete m_stopAll;
    m_stopAll = nullptr;
    delete m_banner;
    m_banner = nullptr;
    delete m_panel;
    m_panel = nullptr;
}

} // namespace opentop
