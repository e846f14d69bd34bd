#include "ui/eol/ProductionView.h"

#include "ui/eol/VerdictLook.h"

#include "model/access/StationAccess.h"
#include "model/io/DisplayText.h"
#include "model/station/EolStation.h"
#include "ui/eol/EolSpeedChart.h"
#include "ui/eol/IdentityDialog.h"
#include "ui/eol/StationActions.h"
#include "ui/eol/StationFigures.h"
#include "ui/eol/StationLogin.h"
#include "ui/widgets/PlainText.h"

#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QShortcut>
#include <QSplitter>
#include <QTableWidget>
#include <QTime>
#include <QTimer>
#include <QVBoxLayout>

namespace opentop {

namespace {

QTableWidget* table(const QStringList& headers, QWidget* parent)
{
    auto* t = new QTableWidget(0, int(headers.size()), parent);
    t->setHorizontalHeaderLabels(headers);
    t->horizontalHeader()->setStretchLastSection(true);
    t->verticalHeader()->hide();
    t->setEditTriggers(QAbstractItemView::NoEditTriggers);
    t->setSelectionMode(QAbstractItemView::NoSelection);
    t->setFocusPolicy(Qt::NoFocus); // the serial field keeps the scanner's keys
    return t;
}

} // namespace

ProductionView::ProductionView(EolStation* station, std::function<ModbusClient*()> client,
                               TrafficLog* traffic, QWidget* parent)
    : QWidget(parent)
    , m_station(station)
    , m_client(std::move(client))
{
    setObjectName(QStringLiteral("productionView"));
    // The station: recipe, per-unit values, results database, operator.
    m_recipe = new QLabel(this);
    auto* openRecipe = new QPushButton(tr("Open recipe…"), this);
    auto* openValues = new QPushButton(tr("Per-unit values…"), this);
    m_database = new QLabel(this);
    m_database->setTextFormat(Qt::PlainText); // the station's name, the database's address
    m_notice = new StationNotice(station, this);
    m_login = new StationLogin(station, this);
    auto* top = new QHBoxLayout;
    top->addWidget(new QLabel(tr("Recipe:"), this));
    top->addWidget(m_recipe, 1);
    top->addWidget(openRecipe);
    top->addWidget(openValues);
    top->addSpacing(12);
    top->addWidget(m_login);

    m_entry = new SerialEntry(station, m_client, traffic, this);

    m_verdict = new QLabel(this);
    m_verdict->setObjectName(QStringLiteral("verdictLabel"));
    m_verdict->setAlignment(Qt::AlignCenter);
    m_verdict->setFont(VerdictLook::scaled(font(), 5.0, true));
    m_verdict->setMinimumHeight(m_verdict->fontMetrics().height() + 16);
    m_reason = new QLabel(this);
    m_reason->setTextFormat(Qt::PlainText); // serials, names, reasons
    m_reason->setWordWrap(true);
    m_reason->setAlignment(Qt::AlignCenter);
    m_reason->setFont(VerdictLook::scaled(font(), 1.5));
    m_reason->setTextInteractionFlags(Qt::TextSelectableByMouse);

    m_drives = table({tr("Drive"), tr("Now")}, this);
    m_chart = new EolSpeedChart(this);
    auto* middle = new QSplitter(Qt::Horizontal, this);
    middle->addWidget(m_drives);
    middle->addWidget(m_chart);
    middle->setStretchFactor(1, 2);

    m_units = new UnitLog(this);
    m_counters = new StationFigures(m_station, this);
    m_counters->setFont(VerdictLook::scaled(font(), 1.3, true));

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addWidget(m_database);
    layout->addWidget(m_login->notice());
    layout->addWidget(m_notice);
    layout->addWidget(m_entry);
    layout->addWidget(m_verdict);
    layout->addWidget(m_reason);
    m_actions = new StationActions(
        m_station, m_client, [this] { return m_station->operatorName().trimmed(); }, this);
    layout->addWidget(m_actions);
    layout->addWidget(middle, 3);
    layout->addWidget(m_counters);
    layout->addWidget(m_units, 2);

    connect(openRecipe, &QPushButton::clicked, this, &ProductionView::chooseRecipe);
    connect(openValues, &QPushButton::clicked, this, &ProductionView::chooseUnitValues);
    connect(m_entry, &SerialEntry::notStarted, this, [this](const QString& why) {
        showVerdict(VerdictLook::State::NotStarted, why);
        focusSerial();
    });
    connect(m_entry, &SerialEntry::waitingForSafety, this, [this](const QString& serial) {
        showVerdict(VerdictLook::State::Testing,
                    tr("Unit %1: making the station's drives safe first…").arg(serial));
    });
    auto* escape = new QShortcut(QKeySequence(Qt::Key_Escape), this);
    escape->setContext(Qt::WidgetWithChildrenShortcut);
    connect(escape, &QShortcut::activated, this, [this] {
        if (m_station->isRunning() || m_station->isStarting())
            m_station->cancel();
    });
    connect(m_login, &StationLogin::loggedIn, this, &ProductionView::focusSerial);
    connect(m_station->access(), &StationAccess::changed, this, [this] {
        if (m_login->needsLogin() && isVisible())
            m_login->focusUser();
    });
    connect(m_station, &EolStation::unitStarted, this, &ProductionView::unitStarted);
    connect(m_station, &EolStation::phaseChanged, this,
            [this](int n, EolDriveRun::Phase phase, const QString& text) {
                phaseChanged(n, int(phase), text);
            });
    connect(m_station, &EolStation::speedSampled, this,
            [this](int n, double speed, const QString& unit) {
                m_chart->add(n, m_clock.elapsed() / 1000.0, speed, unit);
            });
    connect(m_station, &EolStation::unitFinished, this, &ProductionView::unitFinished);
    connect(m_station, &EolStation::unsavedResultChanged, this,
            &ProductionView::unsavedResultChanged);
    connect(m_station, &EolStation::databaseOpened, this, [this] { refresh(); });
    connect(m_station, &EolStation::startRefused, this, [this](const QString&, const QString& why) {
        showVerdict(VerdictLook::State::NotStarted, why);
        m_entry->cancelButton()->setEnabled(false);
        refreshRecipe();
        focusSerial();
    });
    connect(m_station, &EolStation::retestNeedsTechnician, this,
            [this](const QString&, const QString& why) {
                showVerdict(VerdictLook::State::NotStarted, why);
                m_entry->cancelButton()->setEnabled(false);
                focusSerial();
            });
    connect(m_station, &EolStation::recording, this, [this](const QString& what) {
        if (!m_station->run())
            return;
        const QString serial = m_station->run()->record().serial;
        m_reason->setText(DisplayText::escapedLines(
            what.isEmpty() ? tr("Unit %1").arg(serial) : tr("Unit %1: %2…").arg(serial, what)));
    });
    showVerdict(VerdictLook::State::Ready, QString());
    refreshRecipe();
    refreshCounters();
}

void ProductionView::refresh()
{
    refreshRecipe();
    refreshCounters();
}

void ProductionView::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    QTimer::singleShot(0, this, &ProductionView::focusSerial);
}

void ProductionView::focusSerial()
{
    if (m_login->needsLogin()) { // a badge's keys go to the login first
        m_login->focusUser();
        return;
    }
    m_entry->field()->setFocus();
    m_entry->field()->selectAll();
}

bool ProductionView::openRecipe(const QString& path)
{
    QStringList problems;
    if (!m_station->loadRecipe(path, &problems)) {
        PlainText::warning(
            this, tr("Recipe not usable"),
            tr("%1 cannot be run; nothing will be sent:\n\n%2")
                .arg(QDir::toNativeSeparators(path), problems.join(QLatin1Char('\n'))));
        return false;
    }
    refreshRecipe();
    m_login->refresh();
    if (isVisible())
        makeSafe();
    focusSerial();
    return true;
}

void ProductionView::makeSafe()
{
    if (ModbusClient* client = m_client())
        m_station->makeSafe(client);
}

void ProductionView::chooseRecipe()
{
    // Another recipe changes what the line builds: an engineer's, on a managed station.
    IdentityDialog::ask(m_station->access(), Privilege::EditRecipe, tr("open another recipe"), this,
                        [this](const AccessDecision&) {
                            const QString path = QFileDialog::getOpenFileName(
                                this, tr("Open recipe"), QString(), tr("Recipes (*.json)"));
                            if (!path.isEmpty())
                                openRecipe(path);
                        });
}

void ProductionView::chooseUnitValues()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Per-unit values"), QString(),
                                                      tr("CSV files (*.csv)"));
    if (path.isEmpty())
        return;
    QString error;
    if (!m_station->loadUnitValues(path, &error))
        PlainText::warning(this, tr("Per-unit values"), DisplayText::escapedLines(error));
    refreshRecipe();
}

void ProductionView::refreshRecipe()
{
    m_recipe->setText(
        m_station->hasRecipe()
            ? tr("<b>%1</b> rev. %2 — %n drive(s)", nullptr,
                 int(m_station->recipe().positions.size()))
                  .arg(DisplayText::escaped(m_station->recipe().product).toHtmlEscaped(),
                       DisplayText::escaped(m_station->recipe().revision).toHtmlEscaped())
            : tr("<i>none: open the product's recipe</i>"));
    m_database->setText(tr("Station %1 · results: %2 · per-unit values: %3")
                            .arg(DisplayText::escaped(m_station->station()),
                                 DisplayText::escaped(m_station->databaseText()),
                                 m_station->hasUnitValues() ? tr("loaded") : tr("none")));
    m_entry->field()->setEnabled(m_station->hasRecipe() && !m_station->hasUnsavedResult());
}

QLabel* ProductionView::countersLabel() const
{
    return m_counters;
}

void ProductionView::refreshCounters()
{
    m_counters->refresh();
}

void ProductionView::showVerdict(VerdictLook::State state, const QString& reason)
{
    m_verdict->setText(VerdictLook::text(state));
    m_verdict->setStyleSheet(
        QStringLiteral("QLabel { background: %1; color: white; border-radius: 6px; }")
            .arg(VerdictLook::colour(state)));
    // Serials, reasons and names in it are the station's and the recipe's (DisplayText); the
    // lines the program made stay lines.
    m_reason->setText(DisplayText::escapedLines(reason));
}

void ProductionView::unitStarted(const QString& serial)
{
    m_clock.start();
    m_chart->clear();
    m_drives->setRowCount(0);
    for (const RecipePosition& p : m_station->recipe().positions) {
        const int row = m_drives->rowCount();
        m_drives->insertRow(row);
        m_drives->setItem(
            row, 0,
            new QTableWidgetItem(
                p.name.isEmpty()
                    ? tr("drive %1").arg(p.machineNumber)
                    : tr("drive %1 (%2)").arg(p.machineNumber).arg(DisplayText::escaped(p.name))));
        m_drives->setItem(row, 1, new QTableWidgetItem(tr("waiting")));
        m_drives->item(row, 0)->setData(Qt::UserRole, p.machineNumber);
    }
    const int attempt = m_station->lastDecision().attempt;
    showVerdict(VerdictLook::State::Testing,
                attempt > 1 ? tr("Unit %1 — attempt %2").arg(serial).arg(attempt)
                            : tr("Unit %1").arg(serial));
    m_entry->unitStarted();
}

void ProductionView::phaseChanged(int machineNumber, int, const QString& text)
{
    for (int row = 0; row < m_drives->rowCount(); ++row)
        if (m_drives->item(row, 0)->data(Qt::UserRole).toInt() == machineNumber)
            m_drives->item(row, 1)->setText(DisplayText::escaped(text));
}

void ProductionView::unitFinished(const UnitRecord& record)
{
    m_entry->cancelButton()->setEnabled(false);
    QString reason = record.failureReason;
    if (m_station->hasUnsavedResult()) {
        // Never a verdict the database does not hold: red, and nothing else is tested.
        showNotRecorded();
    } else if (m_station->lastResultSpooled()) {
        showVerdictOf(record, (reason.isEmpty() ? tr("Unit %1").arg(record.serial) : reason) +
                                  QLatin1Char('\n') +
                                  tr("Kept on this station: the results server did not answer. "
                                     "It is sent by itself when the server answers."));
    } else {
        showVerdictOf(record, reason);
    }
    if (!m_station->unconfirmedStops().isEmpty())
        PlainText::critical(this, tr("Motor not confirmed stopped"),
                            tr("These motors may still be turning; stop them before touching "
                               "the unit:\n\n%1")
                                .arg(DisplayText::escapedLines(
                                    m_station->unconfirmedStops().join(QLatin1Char('\n')))));
    m_units->add(record, m_station->hasUnsavedResult()    ? UnitLog::Kept::NotRecorded
                         : m_station->lastResultSpooled() ? UnitLog::Kept::OnStation
                                                          : UnitLog::Kept::Recorded);
    refreshCounters();
    refreshRecipe();
    m_entry->field()->clear();
    focusSerial();
}

void ProductionView::showNotRecorded()
{
    const UnitRecord& unit = *m_station->unsavedResult();
    showVerdict(
        VerdictLook::State::NotRecorded,
        tr("Unit %1 ended %2, but its result is not in the results database: %3\n"
           "Nothing is tested until it is recorded. The station tries again by itself "
           "(next try at %4); keep the unit aside.")
            .arg(unit.serial, unitStatusName(unit.status).toUpper(), m_station->storeError())
            .arg(QTime::currentTime()
                     .addSecs(m_station->nextRetrySeconds())
                     .toString(QStringLiteral("HH:mm:ss"))));
    refreshCounters();
    m_entry->field()->setEnabled(false);
}

void ProductionView::unsavedResultChanged(bool recorded)
{
    if (!recorded) {
        showNotRecorded();
        return;
    }
    const UnitRecord unit =
        m_station->lastUnits().isEmpty() ? UnitRecord() : m_station->lastUnits().first();
    m_units->markRecorded(unit.status);
    showVerdictOf(unit, tr("%1\nRecorded at %2, after the results database came back.")
                            .arg(unit.failureReason.isEmpty() ? tr("Unit %1").arg(unit.serial)
                                                              : unit.failureReason,
                                 QTime::currentTime().toString(QStringLiteral("HH:mm:ss"))));
    refreshCounters();
    refreshRecipe();
    focusSerial();
}

void ProductionView::showVerdictOf(const UnitRecord& record, const QString& reason)
{
    showVerdict(VerdictLook::of(record.status), VerdictLook::reason(record, reason));
}

} // namespace opentop
