#include "model/station/EolStation.h"

#include "model/access/StationAccess.h"
#include "model/eol/ResultWriter.h"
#include "model/eol/RetestPolicy.h"
#include "model/eol/SerialRule.h"
#include "model/eol/StationYield.h"
#include "model/profile/ProfileRegistry.h"
#include "transport/ModbusClient.h"

#include <QSysInfo>

namespace opentop {

constexpr int kLastUnits = 50; // lastUnits()

EolStation::EolStation(QObject* parent)
    : QObject(parent)
    , m_results(std::make_unique<StationResults>())
    , m_access(new StationAccess(m_results->writer(), this))
    , m_station(QSysInfo::machineHostName())
    , m_yield(new StationYield(m_results->writer(), this))
    , m_gate(new UnitStartGate(ProfileRegistry::builtIn(), this))
    , m_alarms(new LatchedAlarms(ProfileRegistry::builtIn(), this))
{
    m_access->setStation(m_station);
    m_results->setStation(m_station);
    connect(m_gate, &UnitStartGate::safetyChanged, this, &EolStation::safetyChanged);
    connect(m_alarms, &LatchedAlarms::resetStarted, this, &EolStation::alarmResetStarted);
    connect(m_alarms, &LatchedAlarms::resetFinished, this, &EolStation::alarmResetFinished);
    connect(m_results->writer(), &ResultWriter::waitingChanged, this,
            &EolStation::resultsWaitingChanged);
    // Results sent from the spool are in the database now: the figures count them.
    connect(m_results->writer(), &ResultWriter::waitingChanged, this, [this] { refreshYield(); });
    connect(m_results.get(), &StationResults::opened, this,
            [this](bool ok, const QString& error, const QVector<StationLease::Leftover>& left) {
                if (ok) {
                    refreshYield();
                    m_access->refresh(m_recipe.checksum());
                    if (!left.isEmpty())
                        emit interruptedFound(left);
                }
                emit databaseOpened(ok, error);
            });
    connect(m_results.get(), &StationResults::unsavedAnswered, this,
            [this](bool recorded, const QString& error) {
                if (recorded)
                    refreshYield(); // the screen's counters hold what the database holds
                emit unsavedResultChanged(recorded, error);
            });
}

EolStation::~EolStation()
{
    // A unit still running is cancelled by whoever closes the station first (the screen asks);
    // here only its run object goes.
    delete m_run;
}

bool EolStation::loadRecipe(const QString& path, QStringList* problems)
{
    if (!m_recipe.load(path, problems))
        return false;
    m_gate->forgetSafe(); // its positions are made safe before its first unit
    m_alarms->set({});
    refreshYield();
    if (m_results->writer()->isOpen())
        m_access->refresh(m_recipe.checksum()); // is this checksum approved?
    return true;
}

void EolStation::openDatabase(const QString& url)
{
    m_results->open(url); // opened() answers each try
}

bool EolStation::openDatabaseAndWait(const QString& url, QString* error)
{
    QVector<StationLease::Leftover> left;
    if (!m_results->openAndWait(url, error, &left))
        return false;
    m_access->refresh(m_recipe.checksum());
    if (!left.isEmpty())
        emit interruptedFound(left);
    refreshYield();
    return true;
}

bool EolStation::setStation(const QString& station)
{
    const QString name = station.trimmed();
    if (name.isEmpty() || isRunning())
        return false;
    if (name == m_station)
        return true;
    m_station = name;
    m_access->setStation(name);
    m_results->setStation(name);
    if (m_results->writer()->isOpen())
        openDatabase(m_results->url()); // the lease names the station
    return true;
}

bool EolStation::hasDatabase() const
{
    // Open and its users read: whether units need a login is known before the first scan.
    return m_results->writer()->isOpen() && m_access->state() != StationAccess::State::Unknown;
}

bool EolStation::isOpeningDatabase() const
{
    return m_results->writer()->isOpening() ||
           (m_results->writer()->isOpen() && m_access->state() == StationAccess::State::Unknown);
}

bool EolStation::start(ModbusClient* client, TrafficLog* traffic, const QString& serial,
                       const QHash<int, QHash<QString, double>>& typed, QString* error,
                       const QString& retestBy)
{
    if (isRunning()) {
        *error = tr("a unit is being tested");
        return false;
    }
    if (!m_recipe.has()) {
        *error = tr("open a recipe first");
        return false;
    }
    // Before anything else: a refused serial reaches no audit trail, database or drive.
    const QString badSerial = serialProblem(serial);
    if (!badSerial.isEmpty()) {
        *error = badSerial;
        return false;
    }
    const QString unrecorded = m_results->refusal(); // nothing is tested unless it is recorded
    if (!unrecorded.isEmpty()) {
        *error = unrecorded;
        return false;
    }
    const QString refused =
        m_access->runRefusal(m_recipe.recipe().product, m_recipe.recipe().revision);
    if (!refused.isEmpty()) {
        *error = refused;
        if (m_access->user())
            m_access->audit(QStringLiteral("refused"),
                            tr("run-units: serial %1: %2").arg(serial, refused));
        return false;
    }
    if (!client) {
        *error = tr("not connected to a bus");
        return false;
    }
    if (m_gate->isPending()) {
        *error = tr("unit %1 starts as soon as the station's drives are safe")
                     .arg(m_gate->pendingSerial());
        return false;
    }
    UnitStartGate::Unit unit;
    unit.recipe = m_recipe.recipe();
    EolRun::Options& options = unit.options;
    options.serial = serial;
    options.station = m_station;
    options.operatorName = m_access->isManaged() ? m_access->operatorName() : m_operator;
    options.recipeChecksum = m_recipe.checksum();
    if (m_access->isManaged() && m_access->approval()) {
        options.approvalId = m_access->approval()->id;
        options.approver = m_access->approval()->approver;
    }
    options.timing = m_timing;
    options.writer = m_results->writer();
    options.traffic = traffic;
    const auto values = m_recipe.unitValues(options.serial, typed, error);
    if (!values)
        return false;
    options.unitValues = *values;
    // The gate decides (retest → safe → begin); asking a technician is the screen's
    // (StationActions), `retestBy` is who allowed it.
    unit.technicianAllows = !retestBy.isEmpty();
    unit.client = [client = QPointer<ModbusClient>(client)] { return client.data(); };
    unit.retestPassed = [this, serial = options.serial, retestBy](const RetestPolicy::Decision& d) {
        if (d.kind == RetestPolicy::Decision::Kind::Allowed)
            return;
        // An override of the recipe's rules: in the audit trail, whoever gave it.
        m_access->audit(
            QStringLiteral("retest-override"),
            tr("serial %1 tested again, allowed by %2: %3").arg(serial, retestBy, d.reason));
        emit retestAllowed(serial, d.reason, retestBy);
    };
    unit.made = [this](EolRun* run, ModbusClient* bus) { begin(run, bus); };
    unit.finished = [this](const UnitRecord& record) { finished(record); };
    m_lastStart = {options.serial, typed, traffic};
    m_gate->start(unit, [this](const UnitStartGate::Outcome& o) {
        using Kind = UnitStartGate::Outcome::Kind;
        if (o.kind == Kind::NeedsTechnician)
            emit retestNeedsTechnician(o.serial, o.message);
        else if (o.kind != Kind::Begun)
            emit startRefused(o.serial, o.message);
    });
    return true;
}

QString EolStation::serialProblem(const QString& serial) const
{
    return SerialRule::problem(serial, m_recipe.recipe());
}

void EolStation::begin(EolRun* run, ModbusClient* client)
{
    delete m_run;
    m_run = run;
    run->setParent(this);
    connect(m_run, &EolRun::phaseChanged, this, &EolStation::phaseChanged);
    connect(m_run, &EolRun::measured, this, &EolStation::measured);
    connect(m_run, &EolRun::speedSampled, this, &EolStation::speedSampled);
    connect(m_run, &EolRun::recording, this, &EolStation::recording);
    // A vanished port ends the unit at once (whatever can still be stopped is).
    connect(client, &ModbusClient::connectionLost, m_run,
            [run](const QString& why) { run->connectionLost(why); });
    m_unconfirmed.clear();
    m_results->unitBegun();
    emit unitStarted(m_lastStart.serial); // the unit the gate was given
}

bool EolStation::startAgain(ModbusClient* client, const QString& retestBy, QString* error)
{
    const LastStart last = m_lastStart;
    if (last.serial.isEmpty()) {
        *error = tr("no unit was started yet");
        return false;
    }
    return start(client, last.traffic, last.serial, last.typed, error, retestBy);
}

void EolStation::cancel(const QString& reason)
{
    if (m_gate->cancel(reason)) // nothing was sent for it yet: startRefused() says so
        return;
    if (m_run)
        m_run->cancel(reason);
}

void EolStation::connectionLost(const QString& error)
{
    m_gate->forgetSafe();
    if (m_run)
        m_run->connectionLost(error);
}

void EolStation::finished(const UnitRecord& record)
{
    m_alarms->set(m_run ? m_run->latchedAlarms() : QVector<int>());
    m_gate->unitEnded(record, m_recipe.recipe()); // not ended cleanly: made safe again at once
    m_unconfirmed = m_run ? m_run->unconfirmedStops() : QStringList();
    // The screen's figures are read back from the database (StationYield): what it holds, the
    // same as `eol results --yield`, a restart included. A verdict it does not hold is kept and
    // tried again (StationResults), and the station tests nothing meanwhile.
    if (m_results->unitEnded(record, m_run ? m_run->storeError() : QString(),
                             m_run && m_run->spooled()))
        refreshYield();
    m_access->refresh(m_recipe.checksum()); // an approval superseded meanwhile stops the next unit
    m_last.prepend(record);
    if (m_last.size() > kLastUnits)
        m_last.removeLast();
    emit unitFinished(record);
}

void EolStation::refreshYield()
{
    if (m_recipe.has() && m_results->writer()->isOpen())
        m_yield->refresh(m_station, m_recipe.checksum());
}

void EolStation::resetAlarmsAndRetry(ModbusClient* client)
{
    if (m_alarms->machineNumbers().isEmpty() || m_alarms->isResetting() || isRunning() ||
        isStarting() || !client)
        return;
    m_alarms->reset(client, m_recipe.recipe(), [this, client = QPointer<ModbusClient>(client)] {
        if (!client)
            return;
        // The same unit again: its serial and typed values as the operator gave them.
        QString error;
        if (!startAgain(client, QString(), &error))
            emit startRefused(m_lastStart.serial, error);
    });
}

void EolStation::makeSafe(ModbusClient* client)
{
    if (m_recipe.has())
        m_gate->makeSafe(client, m_recipe.recipe()); // not while under way or a unit runs
}

} // namespace opentop
