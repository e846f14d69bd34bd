#include "model/eol/EolRun.h"

#include "model/ModelLog.h"
#include "model/eol/RecipeChecker.h"
#include "model/eol/ResultWriter.h"
#include "model/profile/ProfileRegistry.h"
#include "model/run/RunControl.h"
#include "transport/TrafficLog.h"

#include <QDateTime>
#include <QTimer>

namespace opentop {

EolRun::EolRun(ModbusClient* client, const ProfileRegistry& registry, const Recipe& recipe,
               const Options& options, QObject* parent)
    : QObject(parent)
    , m_client(client)
    , m_registry(registry)
    , m_recipe(recipe)
    , m_options(options)
    , m_run(new RunControl(client, registry, this))
{
    m_run->setStopTiming(options.timing.stop);
}

EolRun::~EolRun() = default;

void EolRun::start(Done done)
{
    m_done = std::move(done);
    m_elapsed.start();
    m_record = UnitRecord();
    m_record.serial = m_options.serial;
    m_record.station = m_options.station;
    m_record.operatorName = m_options.operatorName;
    m_record.recipeName = m_recipe.product;
    m_record.recipeRevision = m_recipe.revision;
    m_record.recipeChecksum = m_options.recipeChecksum;
    m_record.approvalId = m_options.approvalId;
    m_record.approver = m_options.approver;
    m_record.started = QDateTime::currentDateTimeUtc();
    m_record.status = UnitStatus::Running;
    // Nothing is sent for a recipe or unit values that are not valid (the callers check first;
    // this is the last line).
    const QString invalid = problemOf();
    if (!invalid.isEmpty()) {
        m_firstFailure = invalid;
        m_cancelled = true;
        QTimer::singleShot(0, this, [this] { finish(); });
        return;
    }
    // Recorded as running before anything is sent: a station killed from here on leaves a row
    // that is visibly not a pass. A unit that cannot be recorded is not tested.
    if (!m_options.writer) {
        startDrives();
        return;
    }
    emit recording(tr("recording the unit before anything is sent"));
    m_options.writer->beginUnit(
        m_record, this, [this](const UnitRecord& begun, const ResultWriter::Saved& saved) {
            if (!saved.error.isEmpty()) {
                m_storeError = saved.error;
                m_firstFailure =
                    tr("the results database cannot record the unit: %1").arg(saved.error);
                m_cancelled = true;
                m_stationError = true;
                finish();
                return;
            }
            m_record.id = begun.id;
            m_record.started = begun.started;
            m_record.attempt = begun.attempt; // 0 while it waits in the spool
            emit recording(QString());
            if (m_cancelled) // while it was being recorded: nothing was sent
                finish();
            else
                startDrives();
        });
}

void EolRun::startDrives()
{
    for (int i = 0; i < m_recipe.positions.size(); ++i) {
        const RecipePosition& position = m_recipe.positions[i];
        auto* drive = new EolDriveRun(m_client, m_registry, m_run, position, i,
                                      m_options.unitValues.value(position.machineNumber),
                                      m_options.timing, this);
        drive->setVariantEvidence(m_options.assertedVariants.value(position.machineNumber),
                                  m_options.operatorName);
        connect(drive, &EolDriveRun::phaseChanged, this, &EolRun::phaseChanged);
        connect(drive, &EolDriveRun::measured, this, &EolRun::measured);
        connect(drive, &EolDriveRun::speedSampled, this, &EolRun::speedSampled);
        m_drives.append(drive);
    }
    m_remaining = m_drives.size();
    if (!m_remaining) {
        m_firstFailure = tr("the recipe has no drives");
        QTimer::singleShot(0, this, [this] { finish(); });
        return;
    }
    for (EolDriveRun* drive : m_drives)
        drive->start([this, drive] { driveDone(drive); });
}

QString EolRun::problemOf() const
{
    const RecipeChecker checker(m_registry);
    const QVector<RecipeProblem> problems = checker.check(m_recipe);
    if (!problems.isEmpty())
        return tr("the recipe is not valid: %1").arg(problems.first().message);
    for (const RecipePosition& p : m_recipe.positions) {
        const QHash<QString, double> values = m_options.unitValues.value(p.machineNumber);
        for (const RecipeUnitValue& u : p.unitValues) {
            if (!values.contains(u.name))
                return tr("%1: no value for %2 for this unit")
                    .arg(Recipe::positionText(int(&p - m_recipe.positions.constData()),
                                              p.machineNumber),
                         RecipeChecker::labelOf(*m_registry.family(p.family), u.name));
            const QString why =
                checker.checkUnitValue(m_recipe, p.machineNumber, u.name, values.value(u.name));
            if (!why.isEmpty())
                return why;
        }
    }
    return QString();
}

void EolRun::cancel(const QString& reason)
{
    if (!m_done || m_cancelled || m_recording)
        return;
    m_cancelled = true;
    const QString why = reason.isEmpty() ? tr("cancelled by the operator") : reason;
    if (m_firstFailure.isEmpty())
        m_firstFailure = why;
    for (EolDriveRun* drive : m_drives)
        drive->abort(why);
}

void EolRun::connectionLost(const QString& error)
{
    if (m_firstFailure.isEmpty())
        m_stationError = true; // the station's port, not the unit
    cancel(tr("the connection was lost: %1").arg(error));
}

void EolRun::driveDone(EolDriveRun* drive)
{
    if (drive->alarmLatched())
        m_latchedAlarms << drive->machineNumber();
    if (!drive->ok() && m_firstFailure.isEmpty()) {
        m_firstFailure = tr("%1: %2").arg(drive->title(), drive->failure());
        m_stationError = drive->stationError();
        // One failed drive fails the unit: the others end now, their motors stopped.
        for (EolDriveRun* other : m_drives)
            if (other != drive)
                other->abort(tr("%1 failed").arg(drive->title()));
    }
    if (!drive->stopConfirmed())
        m_unconfirmed << tr("%1: %2").arg(drive->title(), drive->stopDetail());
    if (--m_remaining == 0)
        finish();
}

QStringList EolRun::trafficLines() const
{
    QStringList lines;
    if (!m_options.traffic)
        return lines;
    const QVector<TrafficEntry> entries = m_options.traffic->entries();
    const QDateTime since = m_record.started.addSecs(-1);
    for (int i = std::max(0, int(entries.size()) - m_options.trafficLines); i < entries.size(); ++i)
        if (entries[i].time >= since)
            lines << entries[i].toLine();
    return lines;
}

void EolRun::finish()
{
    if (!m_done || m_recording)
        return;
    for (EolDriveRun* drive : m_drives) {
        m_record.drives.append(drive->drive());
        m_record.writtenValues += drive->writtenValues();
        m_record.measurements += drive->measurements();
    }
    if (m_firstFailure.isEmpty()) {
        m_record.status = UnitStatus::Pass;
    } else {
        m_record.status = m_stationError ? UnitStatus::Error
                          : m_cancelled  ? UnitStatus::Aborted
                                         : UnitStatus::Fail;
        m_record.failureReason = m_firstFailure;
        if (!m_unconfirmed.isEmpty())
            m_record.failureReason +=
                QStringLiteral("; ") +
                tr("NOT CONFIRMED STOPPED: %1").arg(m_unconfirmed.join(QStringLiteral("; ")));
        m_record.traffic = trafficLines();
    }
    m_record.ended = QDateTime::currentDateTimeUtc();
    if (!m_options.writer || m_record.id.isEmpty()) {
        complete();
        return;
    }
    m_recording = true;
    emit recording(tr("recording the result"));
    m_options.writer->finishUnit(m_record, this, [this](const ResultWriter::Saved& saved) {
        if (!saved.error.isEmpty()) {
            m_storeError = saved.error;
            qCWarning(lcModel) << "unit record not completed" << saved.error;
        }
        m_spooled = saved.spooled;
        complete();
    });
}

void EolRun::complete()
{
    m_recording = false;
    qCDebug(lcModel) << "unit" << m_record.serial << unitStatusName(m_record.status) << "in"
                     << m_elapsed.elapsed() << "ms" << m_record.failureReason;
    Done done = std::move(m_done);
    m_done = nullptr;
    emit finished(m_record);
    done(m_record);
}

} // namespace opentop
