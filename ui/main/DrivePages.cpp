#include "ui/main/DrivePages.h"

#include "model/bus/BusDrives.h"
#include "model/bus/DriveName.h"
#include "model/bus/DriveStatusPoller.h"
#include "model/session/DeviceParameters.h"
#include "model/session/DeviceSession.h"
#include "model/tuning/TuningSpec.h"
#include "ui/alarms/AlarmsPage.h"
#include "ui/bus/BusListModel.h"
#include "ui/bus/BusPanel.h"
#include "ui/main/MainWindow.h"
#include "ui/monitor/MonitorPage.h"
#include "ui/pages/DcControllerPage.h"
#include "ui/run/StopAllButton.h"
#include "ui/run/TestRunPanel.h"
#include "ui/tuning/TuningPage.h"
#include "ui/workspace/DriveWorkspace.h"

#include <QItemSelectionModel>
#include <QScrollArea>
#include <QTabWidget>
#include <QTableView>

namespace opentop {

DrivePages::DrivePages(MainWindow* window)
    : QObject(window)
    , m_window(window)
{
}

void DrivePages::clear()
{
    DriveWorkspace* workspace = m_window->workspace();
    while (workspace->tabs()->count() > 0)
        delete workspace->tabs()->widget(0);
    workspace->setDrive(nullptr, QString());
}

AlarmsPage* DrivePages::alarmsPage() const
{
    QTabWidget* tabs = m_window->workspace()->tabs();
    for (int i = 0; i < tabs->count(); ++i) {
        if (auto* page = qobject_cast<AlarmsPage*>(tabs->widget(i)))
            return page;
    }
    return nullptr;
}

void DrivePages::showAlarmsOf(int slave)
{
    BusPanel* panel = m_window->busPanel();
    BusDrives* drives = m_window->drives();
    if (!panel || !drives || !drives->contains(slave))
        return;
    const int row = panel->model()->rowOf(slave);
    if (panel->selectedSlaves() != QVector<int>{slave}) {
        // This drive alone (a row added to a selection of several would open the first's).
        const QModelIndex index = panel->model()->index(row, 0);
        panel->view()->selectionModel()->setCurrentIndex(
            index, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    }
    // The pages follow the selection at once; make sure they are this drive's.
    showDrive({slave});
    if (AlarmsPage* page = alarmsPage()) {
        m_window->workspace()->tabs()->setCurrentWidget(page);
        page->refresh();
    }
}

void DrivePages::retitle(int slave)
{
    DriveWorkspace* workspace = m_window->workspace();
    if (workspace->drive() && workspace->drive() == m_window->drives()->parameters(slave))
        workspace->setTitle(driveTitle(slave));
}

void DrivePages::showDrive(const QVector<int>& slaves)
{
    m_selected = slaves;
    BusDrives* drives = m_window->drives();
    DriveWorkspace* workspace = m_window->workspace();
    MonitorHub* hub = m_window->monitorHub();
    // Several drives of one family: one setting can be written to all of them.
    bool sameFamily = slaves.size() > 1;
    for (int s : slaves)
        sameFamily = sameFamily && drives->parameters(s) &&
                     drives->info(s).family == drives->info(slaves.first()).family;
    emit sameFamilySelected(sameFamily);
    if (slaves.isEmpty() || !drives->parameters(slaves.first())) {
        workspace->setDrive(nullptr, QString());
        return;
    }
    const DeviceInfo info = drives->info(slaves.first());
    if (workspace->drive() == drives->parameters(info.slave))
        return;
    workspace->setDrive(drives->parameters(info.slave), driveTitle(info.slave));
    // The monitoring side of the drive: live values, test run and alarm histories.
    auto* monitor = new MonitorPage(hub, drives->parameters(info.slave), workspace->tabs());
    // First: what a drive is doing is what one wants to see on selecting it (as on a TOP-1).
    workspace->tabs()->insertTab(0, monitor, tr("Monitor"));
    workspace->tabs()->setCurrentIndex(0);
    // The DC controller's settings page shows what the controller does now, too.
    for (DcControllerPage* page : workspace->findChildren<DcControllerPage*>())
        page->setMonitorHub(hub);
    auto* run = new TestRunPanel(drives, info.slave, workspace->tabs());
    run->setMonitorHub(hub); // live state; the drive is polled (and trended) while shown
    run->setPollingActive(m_window->statusPoller()->isActive());
    // Scrolls rather than raising the window's minimum height above a laptop's screen.
    auto* runScroll = new QScrollArea(workspace->tabs());
    runScroll->setFrameShape(QFrame::NoFrame);
    runScroll->setWidgetResizable(true);
    runScroll->setWidget(run);
    workspace->tabs()->addTab(runScroll, tr("Test run"));
    // Speed loop tuning for a drive whose profile says how its loop is tuned.
    QString why;
    if (const std::optional<TuningSpec> spec =
            TuningSpec::of(drives->session(info.slave)->profile(), &why)) {
        auto* tuning = new TuningPage(
            drives->session(info.slave), *spec,
            DriveName::withModel(info.slave, info.machineName, info.model), workspace->tabs());
        workspace->tabs()->addTab(tuning, tr("Speed loop tuning"));
        // STOP ALL ends a tuning test too (the test would otherwise command the motor again).
        if (StopAllButton* stopAll = m_window->stopAllButton())
            connect(stopAll, &StopAllButton::started, tuning, &TuningPage::cancelTest);
    }
    auto* alarms = new AlarmsPage(drives->session(info.slave), workspace->tabs());
    workspace->tabs()->addTab(alarms, tr("Alarms"));
    // Live: raised, cleared and power-cycled alarms show without a click, as on the banner.
    alarms->followLive(hub, m_window->statusPoller());
    alarms->refresh();
}

QString DrivePages::driveTitle(int slave) const
{
    const DeviceInfo info = m_window->drives()->info(slave);
    // The machine's name first: it is what people call the machine.
    return tr("%1 — %2, firmware V%3, switches %4")
        .arg(DriveName::title(info.slave, info.machineName), info.model, info.firmware,
             DeviceInfo::addressText(info.slave, info.family));
}

} // namespace opentop
