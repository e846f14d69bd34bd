#include "ui/eol/ProductionMode.h"

#include "model/access/StationAccess.h"
#include "model/io/DisplayText.h"
#include "model/station/EolStation.h"
#include "ui/eol/IdentityDialog.h"
#include "ui/eol/ProductionView.h"
#include "ui/widgets/PlainText.h"

#include <QAction>
#include <QBoxLayout>
#include <QDockWidget>
#include <QInputDialog>
#include <QLineEdit>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>
#include <utility>

namespace opentop {

namespace {
constexpr char kStationKey[] = "eol/station";
}

ProductionMode::ProductionMode(QMainWindow* window, QWidget* engineering, QBoxLayout* column,
                               QVector<QMenu*> editingMenus, std::function<ModbusClient*()> client,
                               TrafficLog* traffic)
    : QObject(window)
    , m_window(window)
    , m_engineering(engineering)
    , m_editingMenus(std::move(editingMenus))
    , m_station(new EolStation(this))
{
    m_view = new ProductionView(m_station, std::move(client), traffic, window);
    m_view->hide();
    column->addWidget(m_view, 1);
    m_toggle = new QAction(tr("&Production mode (end of line)"), this);
    m_toggle->setCheckable(true);
    m_toggle->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P));
    m_toggle->setToolTip(tr("The operator screen of an end-of-line station; no parameter "
                            "editing until you switch back (Ctrl+Shift+P)"));
    connect(m_toggle, &QAction::toggled, this, &ProductionMode::setActive);
    m_fullScreen = new QAction(tr("&Full screen"), this);
    m_fullScreen->setCheckable(true);
    m_fullScreen->setShortcut(QKeySequence(Qt::Key_F11));
    connect(m_fullScreen, &QAction::toggled, this,
            [this](bool on) { on ? m_window->showFullScreen() : m_window->showNormal(); });
    // Each station of a line has its own name in the records (two PCs must not share one).
    const QString saved = QSettings().value(QLatin1String(kStationKey)).toString();
    if (!saved.isEmpty())
        m_station->setStation(saved);
    m_stationName = new QAction(tr("&Station name…"), this);
    m_stationName->setToolTip(tr("The name this end-of-line station records with every unit"));
    connect(m_stationName, &QAction::triggered, this, &ProductionMode::askStationName);
    connect(m_station, &EolStation::databaseOpened, this, [this](bool ok, const QString& error) {
        // Said once per outage: the station goes on trying by itself and the screen's status
        // line says so.
        if (ok || !isActive() || std::exchange(m_warnedDatabase, true))
            return;
        // Window-modal, not blocking: the screen and its STOP keys go on behind it.
        auto* box = new QMessageBox(QMessageBox::Warning, tr("Results database"),
                                    tr("%1\n\nNo unit can be tested until results can be "
                                       "recorded. The station tries again by itself.")
                                        .arg(error),
                                    QMessageBox::Ok, m_window);
        box->setObjectName(QStringLiteral("resultsDatabaseWarning"));
        box->setTextFormat(Qt::PlainText); // the database's own words
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
    });
    connect(m_station, &EolStation::databaseOpened, this, [this](bool ok) {
        if (ok)
            m_warnedDatabase = false;
    });
}

void ProductionMode::askStationName()
{
    bool ok = false;
    const QString name =
        QInputDialog::getText(m_window, tr("Station name"),
                              tr("The name this station records with every unit (each station "
                                 "of a line needs its own):"),
                              QLineEdit::Normal, m_station->station(), &ok)
            .trimmed();
    if (!ok || name == m_station->station())
        return;
    if (!m_station->setStation(name)) {
        QMessageBox::warning(m_window, tr("Station name"),
                             name.isEmpty() ? tr("A station needs a name.")
                                            : tr("A unit is being tested: change the name once "
                                                 "it is finished."));
        return;
    }
    QSettings().setValue(QLatin1String(kStationKey), name);
    m_view->refresh();
}

bool ProductionMode::isActive() const
{
    return m_view->isVisible() || m_toggle->isChecked();
}

void ProductionMode::setActive(bool active)
{
    if (!active && m_station->isRunning()) {
        // Leaving while a unit is tested would leave it unwatched: finish or cancel it first.
        QMessageBox::information(m_window, tr("Production mode"),
                                 tr("A unit is being tested. Cancel it (Esc) or let it finish "
                                    "before switching back to engineering mode."));
        const QSignalBlocker block(m_toggle);
        m_toggle->setChecked(true);
        return;
    }
    if (!active && !m_leaving && isActive() && m_station->access()->mayBeManaged()) {
        // Parameters and the recipe editor are behind this: an engineer's privilege.
        {
            const QSignalBlocker block(m_toggle);
            m_toggle->setChecked(true);
        }
        IdentityDialog::ask(m_station->access(), Privilege::LeaveProduction,
                            tr("leave production mode"), m_window, [this](const AccessDecision&) {
                                m_leaving = true;
                                setActive(false);
                                m_leaving = false;
                            });
        return;
    }
    if (!active)
        m_station->access()->logout(); // the next operator logs in again
    if (m_toggle->isChecked() != active) {
        const QSignalBlocker block(m_toggle);
        m_toggle->setChecked(active);
    }
    m_engineering->setVisible(!active);
    m_view->setVisible(active);
    // Their actions are on the toolbar too ("Write all pending"): hidden there as well.
    for (QMenu* menu : m_editingMenus) {
        menu->setEnabled(!active);
        for (QAction* action : menu->actions())
            action->setVisible(!active);
    }
    if (active) {
        m_hiddenDocks.clear();
        for (QDockWidget* dock : m_window->findChildren<QDockWidget*>()) {
            if (dock->isVisible()) {
                m_hiddenDocks << dock;
                dock->hide();
            }
        }
        // On the results thread: a database across the network may take seconds to answer.
        if (!m_station->hasDatabase() && !m_station->isOpeningDatabase())
            m_station->openDatabase(m_station->databaseUrl());
        m_view->refresh();
        m_view->makeSafe();
        m_view->focusSerial();
    } else {
        for (QDockWidget* dock : m_hiddenDocks)
            dock->show();
        m_hiddenDocks.clear();
    }
}

bool ProductionMode::guard(const QString& what, std::function<void()> then)
{
    if (!m_station->isRunning())
        return false;
    const auto answer = PlainText::question(
        m_window, tr("A unit is being tested"),
        tr("Unit %1 is being tested. Cancel it and %2? Its motors are stopped first; the unit is "
           "recorded as aborted.")
            .arg(DisplayText::escaped(m_station->run()->record().serial), what),
        QMessageBox::Yes | QMessageBox::No, QMessageBox::No);
    if (answer != QMessageBox::Yes)
        return true;
    auto connection = std::make_shared<QMetaObject::Connection>();
    *connection = connect(m_station, &EolStation::unitFinished, this,
                          [connection, then = std::move(then)](const UnitRecord&) {
                              QObject::disconnect(*connection);
                              then();
                          });
    m_station->cancel(tr("cancelled to %1").arg(what));
    return true;
}

} // namespace opentop
