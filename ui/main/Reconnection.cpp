#include "ui/main/Reconnection.h"

#include "model/bus/BusDrives.h"
#include "model/bus/BusMemory.h"
#include "model/bus/DriveStatusPoller.h"
#include "ui/bus/BusListModel.h"
#include "ui/bus/BusPanel.h"
#include "ui/main/LinkBar.h"
#include "ui/main/MainWindow.h"
#include "ui/widgets/PlainText.h"
#include "ui/workspace/DriveWorkspace.h"

#include <QAction>
#include <QItemSelectionModel>
#include <QMessageBox>
#include <QPushButton>
#include <QStatusBar>
#include <QTabWidget>
#include <QTableView>

namespace opentop {

namespace {
// How long the first reading of every drive after reconnecting may take before it is reported.
constexpr int kReadAgainLimitMs = 10000;
} // namespace

Reconnection::Reconnection(MainWindow* window)
    : QObject(window)
    , m_window(window)
    , m_action(new QAction(tr("&Reconnect"), this))
    , m_bar(nullptr)
{
    m_action->setObjectName(QStringLiteral("reconnectAction"));
    // Ctrl+R is also Drive ▸ Re-read all: that one is enabled only while connected, this one
    // only while not, so the key reads the drives again either way.
    m_action->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
    m_action->setToolTip(tr("Open the last connection again, with the same drives and page "
                            "(Ctrl+R)"));
    m_action->setEnabled(false);
    connect(m_action, &QAction::triggered, this, &Reconnection::reconnect);
    m_bar = new LinkBar(m_action, window);
    connect(window, &MainWindow::connectionChanged, this, &Reconnection::updateAction);
    connect(window, &MainWindow::linkChanged, this, &Reconnection::updateAction);
}

bool Reconnection::isLastPlace(const ConnectionSettings& settings) const
{
    return m_hasLast && BusMemory::key(settings) == BusMemory::key(m_last);
}

void Reconnection::updateAction()
{
    m_action->setEnabled(m_hasLast && !m_connecting && !m_window->isConnected());
}

void Reconnection::keepView()
{
    BusDrives* drives = m_window->drives();
    if (!drives || !m_hasLast)
        return;
    View view;
    view.key = BusMemory::key(m_last);
    view.types = BusMemory::types(BusMemory::present(*drives));
    if (BusPanel* panel = m_window->busPanel())
        view.selection = panel->selectedSlaves();
    QTabWidget* tabs = m_window->workspace()->tabs();
    if (tabs->currentIndex() >= 0)
        view.page = tabs->tabText(tabs->currentIndex());
    // Drives not identified yet on this connection: what was kept before still holds.
    if (view.types.isEmpty() && m_view.key == view.key)
        return;
    m_view = view;
}

void Reconnection::reconnect()
{
    reconnectWith(m_last);
}

bool Reconnection::reconnectWith(const ConnectionSettings& settings)
{
    if (!m_hasLast || m_connecting || m_window->isConnected() || !isLastPlace(settings))
        return false;
    keepView();
    const QString key = BusMemory::key(settings);
    if (m_view.key != key)
        m_view = View{key, {}, {}, {}};
    if (m_view.types.isEmpty()) // nothing shown before: the drives remembered on this connection
        m_view.types = BusMemory::types(BusMemory::load(key));
    m_restoring = true;
    m_bar->say(tr("Reconnecting to %1…").arg(BusMemory::placeText(settings)), LinkBar::Look::Busy,
               m_loss.isValid() ? m_loss.driveLines() : QString());
    // Copies: the window's teardown keeps its view again, here, while connecting.
    const ConnectionSettings place = settings;
    const QHash<int, QString> types = m_view.types;
    m_window->connectTo(place, types);
    return true;
}

void Reconnection::adopted(const ConnectionSettings& settings)
{
    if (m_restoring && BusMemory::key(settings) != m_view.key)
        m_restoring = false; // another place after all
    m_last = settings;
    m_hasLast = true;
    m_connecting = true;
    delete m_watch;
    m_watch = nullptr;
    if (!m_restoring)
        m_bar->hide();
    updateAction();
}

void Reconnection::opened()
{
    m_connecting = false;
    m_loss = LinkLoss(); // the bus is reachable again, or another one is connected
    updateAction();
    if (!m_restoring)
        return;
    m_bar->say(
        tr("Reconnected to %1: reading every drive again…").arg(BusMemory::placeText(m_last)),
        LinkBar::Look::Busy);
    // The drives are identified again first (asynchronously); then the view comes back.
    BusDrives* drives = m_window->drives();
    m_watch = new QObject(this);
    connect(drives, &BusDrives::driveAdded, m_watch, [this] { restoreView(); });
    connect(drives, &BusDrives::driveChanged, m_watch, [this] { restoreView(); });
    restoreView();
}

void Reconnection::restoreView()
{
    BusDrives* drives = m_window->drives();
    if (!drives)
        return;
    for (auto it = m_view.types.cbegin(); it != m_view.types.cend(); ++it) {
        if (!drives->contains(it.key()) ||
            drives->info(it.key()).state == DeviceInfo::State::Unknown)
            return; // still being identified
    }
    delete m_watch;
    m_watch = nullptr;
    m_restoring = false;
    BusPanel* panel = m_window->busPanel();
    QTableView* view = panel->view();
    view->clearSelection();
    for (int slave : m_view.selection) {
        if (!drives->contains(slave))
            continue;
        const QModelIndex index = view->model()->index(panel->model()->rowOf(slave), 0);
        view->selectionModel()->select(index,
                                       QItemSelectionModel::Select | QItemSelectionModel::Rows);
    }
    // The pages follow the selection at once: the one shown before is found by its title.
    QTabWidget* tabs = m_window->workspace()->tabs();
    for (int i = 0; i < tabs->count(); ++i) {
        if (tabs->tabText(i) == m_view.page)
            tabs->setCurrentIndex(i);
    }
    // Nothing is offered on old news: every drive is read again and what needs a look is said.
    if (DriveStatusPoller* poller = m_window->statusPoller())
        poller->afterFreshCycle(
            this, [this] { readAgain(); }, kReadAgainLimitMs);
}

void Reconnection::readAgain()
{
    BusDrives* drives = m_window->drives();
    DriveStatusPoller* poller = m_window->statusPoller();
    if (!drives || !poller || !m_window->isConnected())
        return;
    bool attention = false;
    const QString text = LinkLoss::readAgain(*drives, *poller, &attention);
    const QString reconnected = tr("Reconnected to %1.").arg(BusMemory::placeText(m_last));
    if (attention)
        m_bar->say(reconnected + QLatin1Char(' ') + text, LinkBar::Look::Attention);
    else
        m_bar->hide();
    // The status bar has one line: the drives after the heading, one after the other.
    QStringList lines = text.split(QLatin1Char('\n'));
    QString line = reconnected + QLatin1Char(' ') + lines.takeFirst();
    for (QString& drive : lines)
        drive.remove(0, drive.indexOf(QLatin1Char(' ')) + 1); // the bullet
    if (!lines.isEmpty())
        line += QLatin1Char(' ') + lines.join(QStringLiteral("; "));
    m_window->statusBar()->showMessage(line, 15000);
}

void Reconnection::refused(const QString& why)
{
    if (m_window->isConnected())
        return; // another connection failed; the working one stays
    m_connecting = false;
    m_restoring = false; // the view stays kept for the next try
    delete m_watch;
    m_watch = nullptr;
    if (m_loss.isValid())
        showLoss(tr("Reconnecting failed: %1").arg(why.section(QLatin1Char('\n'), 0, 0)));
    else
        m_bar->hide();
    updateAction();
}

void Reconnection::lost(const QString& explanation)
{
    BusDrives* drives = m_window->drives();
    DriveStatusPoller* poller = m_window->statusPoller();
    if (!drives || !poller)
        return;
    m_connecting = false;
    m_loss = LinkLoss::take(*drives, *poller, BusMemory::placeText(m_last));
    keepView();
    updateAction();
    showLoss();
    // Said at once, with the drives as last known; Reconnect is one click away.
    auto* box = new QMessageBox(QMessageBox::Warning, tr("Connection lost"),
                                m_loss.headline() + QStringLiteral("\n\n") + explanation,
                                QMessageBox::NoButton, m_window);
    // The drives as they reported themselves (their models), the port as it is named.
    box->setTextFormat(Qt::PlainText);
    box->setInformativeText(PlainText::asWritten(
        m_loss.driveLines() +
        (m_loss.leavesAnything() ? QStringLiteral("\n\n") + m_loss.whatToCheck() : QString())));
    QPushButton* again = box->addButton(tr("Reconnect"), QMessageBox::AcceptRole);
    QPushButton* close = box->addButton(QMessageBox::Close);
    box->setDefaultButton(again);
    box->setEscapeButton(close);
    box->setObjectName(QStringLiteral("connectionLostBox"));
    box->setAttribute(Qt::WA_DeleteOnClose);
    connect(box, &QMessageBox::buttonClicked, this, [this, again](QAbstractButton* b) {
        if (b == again) // once the box has closed
            QMetaObject::invokeMethod(this, &Reconnection::reconnect, Qt::QueuedConnection);
    });
    m_message = box;
    box->open();
}

void Reconnection::showLoss(const QString& extra)
{
    m_bar->say(extra.isEmpty() ? m_loss.summary() : m_loss.summary() + QLatin1Char(' ') + extra,
               LinkBar::Look::Lost, m_loss.driveLines());
}

bool Reconnection::wouldAsk() const
{
    return !m_window->isConnected() && m_loss.isValid() && m_loss.leavesAnything();
}

void Reconnection::askLeaving(const QString& leaving, std::function<void()> proceed)
{
    if (!wouldAsk()) {
        proceed();
        return;
    }
    // The message says the same: one window, the question, and nothing over it.
    if (m_message)
        m_message->close();
    // Nothing can be sent over a dead port: no stop is offered; the drives as last known are
    // named with what to check on the machine.
    QMessageBox box(QMessageBox::Warning, tr("Connection lost"), m_loss.exitQuestion(leaving),
                    QMessageBox::NoButton, m_window);
    box.setTextFormat(Qt::PlainText);
    box.setInformativeText(
        PlainText::asWritten(m_loss.driveLines() + QStringLiteral("\n\n") + m_loss.whatToCheck()));
    QPushButton* again = box.addButton(tr("Reconnect"), QMessageBox::AcceptRole);
    QPushButton* leave = box.addButton(tr("Go on anyway"), QMessageBox::DestructiveRole);
    QPushButton* stay = box.addButton(tr("Cancel"), QMessageBox::RejectRole);
    box.setDefaultButton(again);
    box.setEscapeButton(stay);
    box.setObjectName(QStringLiteral("linkLostExitQuestion"));
    QMetaObject::invokeMethod(this, &Reconnection::asking, Qt::QueuedConnection);
    box.exec();
    if (box.clickedButton() == leave) {
        m_loss = LinkLoss(); // told, and chosen: not asked again
        m_bar->hide();
        proceed();
    } else if (box.clickedButton() == again) {
        reconnect();
    }
}

} // namespace opentop
