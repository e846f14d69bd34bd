#include "model/station/EolStation.h"

#include "model/access/StationAccess.h"
#include "model/eol/ResultUrl.h"
#include "model/eol/ResultWriter.h"
#include "model/eol/RetestPolicy.h"
#include "model/eol/StationAlarmReset.h"
#include "model/eol/StationYield.h"
#include "model/profile/ProfileRegistry.h"
#include "transport/ModbusClient.h"

#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QSysInfo>
#include <algorithm>

namespace opentop {

namespace {
constexpr int kLastUnits = 50;
}

EolStation::EolStation(QObject* parent)
    : QObject(parent)
    , m_writer(std::make_unique<ResultWriter>())
    , m_access(new StationAccess(m_writer.get(), this))
    , m_station(QSysInfo::machineHostName())
    , m_yield(new StationYield(m_writer.get(), this))
{
    m_access->setStation(m_station);
    m_retry.setSingleShot(true);
    connect(&m_retry, &QTimer::timeout, this, &EolStation::retryUnsavedNow);
    connect(m_writer.get(), &ResultWriter::waitingChanged, this,
            &EolStation::resultsWaitingChanged);
    // Results sent from the spool are in the database now: the figures count them.
    connect(m_writer.get(), &ResultWriter::waitingChanged, this, [this] { refreshYield(); });
    m_openRetry.setSingleShot(true);
    connect(&m_openRetry, &QTimer::timeout, this, [this] {
        if (!m_writer->isOpen() && !m_writer->isOpening())
            openDatabase(m_dbUrl);
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
    m_safe = false; // its positions are made safe before its first unit
    m_latchedAlarms.clear();
    refreshYield();
    if (m_writer->isOpen())
        m_access->refresh(m_recipe.checksum()); // is this checksum approved?
    return true;
}

void EolStation::openDatabase(const QString& url)
{
    m_dbUrl = url;
    m_openRetry.stop();
    m_writer->open(ResultUrl::stationLocation(url), m_station, this,
                   [this](const ResultWriter::Opened& o) {
                       if (o.ok) {
                           m_dbError.clear();
                           m_openDelayS = 2;
                           refreshYield();
                           m_access->refresh(m_recipe.checksum());
                           if (!o.interrupted.isEmpty()) {
                               m_interrupted = o.interrupted;
                               emit interruptedFound(o.interrupted);
                           }
                       } else {
                           // The screen says so and the station tries again: a line does not wait
                           // for someone to restart it when the server is back.
                           m_dbError = o.error;
                           m_openRetry.start(m_openDelayS * 1000);
                           m_openDelayS = std::min(30, m_openDelayS * 2);
                       }
                       emit databaseOpened(o.ok, o.error);
                   });
}

bool EolStation::openDatabaseAndWait(const QString& url, QString* error)
{
    const ResultWriter::Opened o =
        m_writer->openAndWait(ResultUrl::stationLocation(url), m_station);
    if (!o.ok && error)
        *error = o.error;
    if (o.ok)
        m_access->refresh(m_recipe.checksum());
    if (o.ok && !o.interrupted.isEmpty()) {
        m_interrupted = o.interrupted;
        emit interruptedFound(o.interrupted);
    }
    if (o.ok)
        refreshYield();
    return o.ok;
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
    if (m_writer->isOpen())
        openDatabase(m_dbUrl); // the lease names the station
    return true;
}

bool EolStation::hasDatabase() const
{
    // Open and its users read: whether units need a login is known before the first scan.
    return m_writer->isOpen() && m_access->state() != StationAccess::State::Unknown;
}

bool EolStation::isOpeningDatabase() const
{
    return m_writer->isOpening() ||
           (m_writer->isOpen() && m_access->state() == StationAccess::State::Unknown);
}

QString EolStation::databaseText() const
{
    if (m_writer->isOpen())
        return m_writer->displayText();
    if (m_writer->isOpening())
        return tr("opening the results database");
    if (!m_dbError.isEmpty())
        return tr("NOT REACHABLE (%1); trying again by itself").arg(m_dbError);
    return tr("no results database");
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
    if (m_unsaved) {
        *error =
            tr("the result of unit %1 (%2) is not in the results database yet: nothing is "
               "tested until it is. The station tries again by itself (%3)")
                .arg(m_unsaved->serial, unitStatusName(m_unsaved->status).toUpper(), m_storeError);
        return false;
    }
    if (!m_writer->isOpen()) {
        *error = m_writer->isOpening()
                     ? tr("the results database is being opened; try again in a moment")
                 : m_dbError.isEmpty()
                     ? tr("the results database is not open; nothing is tested unless it is "
                          "recorded")
                     : tr("the results database cannot be reached (%1); nothing is tested unless "
                          "it is recorded. The station tries again by itself.")
                           .arg(m_dbError);
        return false;
    }
    const QString refused =
        m_access->runRefusal(m_recipe.recipe().product, m_recipe.recipe().revision);
    if (!refused.isEmpty()) {
        *error = refused;
        if (m_access->user())
            m_access->audit(QStringLiteral("refused"),
                            tr("run-units: serial %1: %2").arg(serial.trimmed(), refused));
        return false;
    }
    if (!client) {
        *error = tr("not connected to a bus");
        return false;
    }
    if (m_pendingStart) {
        *error = tr("unit %1 starts as soon as the station's drives are safe").arg(m_pendingSerial);
        return false;
    }
    if (serial.trimmed().isEmpty()) {
        *error = tr("no serial number");
        return false;
    }
    EolRun::Options options;
    options.serial = serial.trimmed();
    options.station = m_station;
    options.operatorName = m_access->isManaged() ? m_access->operatorName() : m_operator;
    options.recipeChecksum = m_recipe.checksum();
    if (m_access->isManaged() && m_access->approval()) {
        options.approvalId = m_access->approval()->id;
        options.approver = m_access->approval()->approver;
    }
    options.timing = m_timing;
    options.writer = m_writer.get();
    options.traffic = traffic;
    const auto values = m_recipe.unitValues(options.serial, typed, error);
    if (!values)
        return false;
    options.unitValues = *values;
    // First the serial's earlier tests are checked against the recipe's retest rules, then the
    // positions are made safe (a station killed mid-test may have left a motor turning); the
    // unit starts by itself once both allow it, or startRefused() / retestNeedsTechnician()
    // say why not.
    m_pendingSerial = options.serial;
    m_pendingStart = [this, client = QPointer<ModbusClient>(client), traffic, options] {
        QString why;
        if (!client)
            why = tr("not connected to a bus");
        else if (!m_safe)
            why = tr("a drive of the station is not safe: %1").arg(unsafeText());
        else
            begin(client, traffic, options);
        if (!why.isEmpty())
            emit startRefused(options.serial, why);
    };
    m_lastStart = {options.serial, typed, traffic};
    const quint64 token = ++m_startToken;
    RetestPolicy::check(m_writer.get(), m_recipe.recipe().retest, options.serial,
                        m_recipe.checksum(), this,
                        [this, token, retestBy,
                         client = QPointer<ModbusClient>(client)](const RetestPolicy::Decision& d) {
                            if (token == m_startToken && m_pendingStart) // else cancelled since
                                retestChecked(d, retestBy, client);
                        });
    return true;
}

void EolStation::retestChecked(const RetestPolicy::Decision& d, const QString& retestBy,
                               ModbusClient* client)
{
    using Kind = RetestPolicy::Decision::Kind;
    m_decision = d;
    if (d.kind == Kind::Refused || (d.kind == Kind::NeedsTechnician && retestBy.isEmpty())) {
        m_pendingStart = nullptr;
        const QString held = std::exchange(m_pendingSerial, QString());
        if (d.kind == Kind::NeedsTechnician)
            emit retestNeedsTechnician(held, d.reason);
        else
            emit startRefused(held, d.reason);
        return;
    }
    if (d.kind != Kind::Allowed) {
        // An override of the recipe's rules: in the audit trail, whoever gave it.
        m_access->audit(QStringLiteral("retest-override"),
                        tr("serial %1 tested again, allowed by %2: %3")
                            .arg(m_lastStart.serial, retestBy, d.reason));
        emit retestAllowed(m_lastStart.serial, d.reason, retestBy);
    }
    if (m_safe && !m_safeState) {
        m_pendingSerial.clear();
        std::exchange(m_pendingStart, nullptr)();
    } else {
        makeSafe(client);
    }
}

void EolStation::begin(ModbusClient* client, TrafficLog* traffic, const EolRun::Options& given)
{
    EolRun::Options options = given;
    options.traffic = traffic;
    delete m_run;
    m_run = new EolRun(client, ProfileRegistry::builtIn(), m_recipe.recipe(), options, this);
    connect(m_run, &EolRun::phaseChanged, this, &EolStation::phaseChanged);
    connect(m_run, &EolRun::measured, this, &EolStation::measured);
    connect(m_run, &EolRun::speedSampled, this, &EolStation::speedSampled);
    connect(m_run, &EolRun::recording, this, &EolStation::recording);
    // A vanished port ends the unit at once (whatever can still be stopped is).
    connect(client, &ModbusClient::connectionLost, m_run,
            [run = m_run.data()](const QString& why) { run->connectionLost(why); });
    m_unconfirmed.clear();
    m_storeError.clear();
    m_client = client;
    emit unitStarted(options.serial);
    m_run->start([this](const UnitRecord& record) { finished(record); });
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
    if (m_pendingStart) { // nothing was sent for it yet
        m_pendingStart = nullptr;
        ++m_startToken;
        emit startRefused(std::exchange(m_pendingSerial, QString()),
                          reason.isEmpty() ? tr("cancelled before it started") : reason);
        return;
    }
    if (m_run)
        m_run->cancel(reason);
}

void EolStation::connectionLost(const QString& error)
{
    m_safe = false;
    if (m_run)
        m_run->connectionLost(error);
}

void EolStation::finished(const UnitRecord& record)
{
    // A unit that did not end cleanly may have left a motor turning or a drive in communication
    // priority: checked again at once, before the next unit.
    m_latchedAlarms = m_run ? m_run->latchedAlarms() : QVector<int>();
    if (record.status == UnitStatus::Aborted || record.status == UnitStatus::Error ||
        (m_run && !m_run->unconfirmedStops().isEmpty())) {
        m_safe = false;
        QTimer::singleShot(0, this, [this] {
            if (m_client)
                makeSafe(m_client);
        });
    }
    m_unconfirmed = m_run ? m_run->unconfirmedStops() : QStringList();
    m_storeError = m_run ? m_run->storeError() : QString();
    m_lastSpooled = m_run && m_run->spooled();
    // A verdict the database does not hold is not a result yet: kept, tried again, and the
    // station tests nothing meanwhile. (A unit never begun sent nothing: nothing to keep.)
    if (!m_storeError.isEmpty() && !record.id.isEmpty()) {
        m_unsaved = record;
        m_retryDelayS = 1;
        scheduleRetry();
    } else {
        count(record);
    }
    m_access->refresh(m_recipe.checksum()); // an approval superseded meanwhile stops the next unit
    m_last.prepend(record);
    if (m_last.size() > kLastUnits)
        m_last.removeLast();
    emit unitFinished(record);
}

void EolStation::count(const UnitRecord&)
{
    // The screen's figures are read back from the database (StationYield): what it holds, the
    // same as `eol results --yield`, a restart included.
    refreshYield();
}

void EolStation::refreshYield()
{
    if (m_recipe.has() && m_writer->isOpen())
        m_yield->refresh(m_station, m_recipe.checksum());
}

void EolStation::resetAlarmsAndRetry(ModbusClient* client)
{
    if (m_latchedAlarms.isEmpty() || m_alarmReset || isRunning() || m_pendingStart || !client)
        return;
    m_alarmReset =
        new StationAlarmReset(client, ProfileRegistry::builtIn(), m_recipe.recipe(), this);
    emit alarmResetStarted(m_latchedAlarms);
    m_alarmReset->reset(m_latchedAlarms, [this, client = QPointer<ModbusClient>(client)](
                                             const QVector<StationAlarmReset::Result>& results) {
        m_alarmReset->deleteLater();
        m_alarmReset = nullptr;
        QStringList texts;
        for (const StationAlarmReset::Result& r : results)
            texts << r.text;
        const bool cleared = StationAlarmReset::allCleared(results);
        if (cleared)
            m_latchedAlarms.clear();
        emit alarmResetFinished(cleared, texts);
        if (!cleared || !client)
            return;
        // The same unit again: its serial and typed values as the operator gave them.
        QString error;
        if (!startAgain(client, QString(), &error))
            emit startRefused(m_lastStart.serial, error);
    });
}

int EolStation::nextRetrySeconds() const
{
    return m_retry.isActive() ? (m_retry.remainingTime() + 999) / 1000 : 0;
}

void EolStation::scheduleRetry()
{
    m_retry.start(m_retryDelayS * 1000);
    m_retryDelayS = std::min(30, m_retryDelayS * 2);
}

void EolStation::retryUnsavedNow()
{
    if (!m_unsaved)
        return;
    m_retry.stop();
    m_writer->finishUnit(*m_unsaved, this, [this](const ResultWriter::Saved& saved) {
        if (!m_unsaved)
            return;
        if (!saved.error.isEmpty()) {
            m_storeError = saved.error;
            scheduleRetry();
            emit unsavedResultChanged(false, saved.error);
            return;
        }
        m_lastSpooled = saved.spooled;
        count(*m_unsaved); // the screen's counters hold what the database holds
        m_unsaved.reset();
        m_storeError.clear();
        emit unsavedResultChanged(true, QString());
    });
}

int EolStation::resultsWaiting() const
{
    return m_writer->waiting();
}

QString EolStation::resultsWaitingError() const
{
    return m_writer->waitingError();
}

void EolStation::sendWaitingResultsNow()
{
    m_writer->flushNow();
}

void EolStation::makeSafe(ModbusClient* client)
{
    if (!client || !m_recipe.has() || m_safeState || isRunning())
        return;
    m_client = client;
    m_safeState = new StationSafeState(client, ProfileRegistry::builtIn(), m_recipe.recipe(), this);
    m_safeState->setStopTiming(m_stopTiming);
    emit safetyChanged();
    m_safeState->run([this](const QVector<PositionSafety>& found) {
        m_safeState->deleteLater();
        m_safeState = nullptr;
        m_safety = found;
        m_safe = unsafeText().isEmpty();
        emit safetyChanged();
        if (std::function<void()> pending = std::exchange(m_pendingStart, nullptr)) {
            m_pendingSerial.clear();
            pending();
        }
    });
}

QString EolStation::unsafeText() const
{
    return PositionSafety::blockingText(m_safety);
}

} // namespace opentop
