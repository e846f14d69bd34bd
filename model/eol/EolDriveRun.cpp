#include "model/eol/EolDriveRun.h"

#include "model/eol/CommLossArm.h"
#include "model/eol/EolSettingsWriter.h"
#include "model/eol/EolTarget.h"
#include "model/eol/Recipe.h"
#include "model/eol/VariantCheck.h"
#include "model/files/BackupDevice.h"
#include "model/profile/ProfileRegistry.h"
#include "model/profile/RoleEvaluator.h"
#include "model/session/DeviceIdentifier.h"
#include "model/session/DeviceInfo.h"
#include "model/session/DeviceSession.h"

#include <QTimer>

namespace opentop {

EolDriveRun::EolDriveRun(ModbusClient* client, const ProfileRegistry& registry, RunControl* run,
                         const RecipePosition& position, int index,
                         QHash<QString, double> unitValues, const EolStepRunner::Timing& timing,
                         QObject* parent)
    : QObject(parent)
    , m_client(client)
    , m_registry(registry)
    , m_run(run)
    , m_position(position)
    , m_index(index)
    , m_unitValues(std::move(unitValues))
    , m_timing(timing)
{
    qRegisterMetaType<opentop::EolDriveRun::Phase>("opentop::EolDriveRun::Phase");
    m_drive.machineNumber = position.machineNumber;
}

EolDriveRun::~EolDriveRun()
{
    // Before the session (an older child): a runner deleted mid-motion sends its stop through it.
    delete m_steps;
}

QString EolDriveRun::title() const
{
    return Recipe::positionText(m_index, m_position.machineNumber);
}

void EolDriveRun::setPhase(Phase phase, const QString& text)
{
    m_phase = phase;
    emit phaseChanged(m_position.machineNumber, phase, text);
}

void EolDriveRun::start(std::function<void()> done)
{
    m_done = std::move(done);
    setPhase(Phase::Identify, tr("identifying"));
    auto* identifier = new DeviceIdentifier(m_client, m_registry, this);
    identifier->identify(m_position.machineNumber, [this, identifier](const DeviceInfo& info) {
        identifier->deleteLater();
        if (!m_ended)
            identified(info);
    });
}

const QVector<WrittenValue>& EolDriveRun::writtenValues() const
{
    static const QVector<WrittenValue> none; // nothing is written before the variant is known
    return m_settings ? m_settings->values() : none;
}

void EolDriveRun::setVariantEvidence(const QString& asserted, const QString& operatorName)
{
    m_assertedVariant = asserted;
    m_operatorName = operatorName;
}

void EolDriveRun::identified(const DeviceInfo& info)
{
    if (info.state != DeviceInfo::State::Present) {
        // Silence or a garbled bus is the station's (cable, fixture, power), not the unit's;
        // a drive that answers as something else is the unit's.
        const QString why =
            info.state == DeviceInfo::State::Absent
                ? tr("no drive answers at machine number %1").arg(m_position.machineNumber)
                : tr("the drive at machine number %1 is not identified: %2")
                      .arg(m_position.machineNumber)
                      .arg(info.detail.isEmpty() ? DeviceInfo::stateText(info.state) : info.detail);
        if (info.state == DeviceInfo::State::Unidentified)
            failIdentity(why);
        else
            failStation(why);
        return;
    }
    m_drive.model = info.model;
    m_drive.firmware = info.firmware;
    m_reportedVariant = info.variant;
    if (info.family != m_position.family) {
        failIdentity(
            tr("a %1 drive, the recipe needs a %2 drive").arg(info.model, m_position.family));
        return;
    }
    if (!m_position.firmware.isEmpty() && !m_position.firmware.contains(info.firmware)) {
        failIdentity(tr("firmware %1, the recipe allows %2")
                         .arg(info.firmware.isEmpty() ? tr("unknown") : info.firmware,
                              m_position.firmware.join(QStringLiteral(", "))));
        return;
    }
    const Profile* profile = m_registry.family(m_position.family);
    if (!profile) {
        fail(tr("no profile for the family %1").arg(m_position.family));
        return;
    }
    // The variant is set once it is known (variantKnown); until then only reads are sent.
    m_session = new DeviceSession(m_client, *profile, m_position.machineNumber, info.variant, this);
    m_session->setLabelsInMessages(true);
    checkStopped();
}

void EolDriveRun::checkVariant()
{
    VariantDecision::Evidence evidence;
    evidence.reported = m_reportedVariant;
    evidence.asserted = m_assertedVariant;
    evidence.operatorName = m_operatorName;
    auto* check = new VariantCheck(m_client, m_session->profile(), m_position, evidence, this);
    if (!check->probeText().isEmpty())
        setPhase(Phase::Identify, check->probeText());
    check->run([this, check](const VariantDecision::Decision& decision) {
        check->deleteLater();
        if (!m_ended)
            variantKnown(decision);
    });
}

void EolDriveRun::variantKnown(const VariantDecision::Decision& decision)
{
    m_drive.variant = decision.variant;
    m_drive.variantSource = decision.source;
    m_drive.variantProof = decision.proof;
    if (!decision.ok) {
        failIdentity(decision.failure);
        return;
    }
    QString error;
    const std::optional<BackupDevice> target =
        EolTarget::build(m_session->profile(), m_position, decision.variant, m_unitValues, &error);
    if (!target) {
        fail(error);
        return;
    }
    BackupDevice settings = *target;
    settings.model = m_drive.model;
    settings.firmware = m_drive.firmware;
    m_session->setVariant(decision.variant);
    m_settings = new EolSettingsWriter(m_session, settings, m_position.machineNumber, this);
    write();
}

void EolDriveRun::failIdentity(const QString& reason)
{
    m_identityError = true;
    fail(reason);
}

void EolDriveRun::checkStopped()
{
    // A motor still turning (left by a station that was killed mid-test, or started at the
    // drive) is not this run's to stop, and an alarm latched before the test (the last unit
    // stalled) is no fault of this unit: nothing is written or started, the station is told.
    const Profile& profile = m_session->profile();
    const ParameterMeta* running = RoleEvaluator::parameter(profile, QStringLiteral("running"));
    const ParameterMeta* alarm = RoleEvaluator::parameter(profile, QStringLiteral("alarmActive"));
    QStringList names;
    for (const ParameterMeta* meta : {running, alarm})
        if (meta && !names.contains(meta->name))
            names << meta->name;
    if (names.isEmpty()) {
        checkVariant();
        return;
    }
    m_session->readMany(names, [this, running, alarm](const DeviceSession::ReadManyOutcome& r) {
        if (m_ended)
            return;
        const auto value = [&r](const QString& name) -> std::optional<double> {
            const auto it = r.results.constFind(name);
            if (it == r.results.cend() || !it->ok)
                return std::nullopt;
            return double(it->value.raw);
        };
        for (const ParameterMeta* meta : {running, alarm}) {
            const auto it = meta ? r.results.constFind(meta->name) : r.results.cend();
            if (meta && (it == r.results.cend() || !it->ok)) {
                failStation(tr("cannot read whether the motor runs or an alarm is active: %1")
                                .arg(it == r.results.cend() ? tr("no answer") : it->error));
                return;
            }
        }
        const Profile& p = m_session->profile();
        if (RoleEvaluator::flag(p, QStringLiteral("running"), value).value_or(false)) {
            m_stopConfirmed = false;
            m_stopDetail = tr("its motor was running before the test");
            failStation(tr("the motor is already running before the test (left by an interrupted "
                           "run?); nothing was written: stop it first (STOP ALL, or at the "
                           "drive)"));
            return;
        }
        if (RoleEvaluator::flag(p, QStringLiteral("alarmActive"), value).value_or(false)) {
            m_alarmLatched = true;
            failStation(tr("an alarm is active before the test (left by the last unit?); "
                           "nothing was written: reset the alarm and test again"));
            return;
        }
        checkVariant();
    });
}

void EolDriveRun::write()
{
    setPhase(Phase::Write, tr("writing the settings"));
    m_settings->write([this](const QString& failure) {
        if (m_ended)
            return;
        if (!failure.isEmpty()) {
            fail(tr("writing the settings: %1").arg(failure));
            return;
        }
        verify();
    });
}

void EolDriveRun::verify()
{
    setPhase(Phase::Verify, tr("reading every setting back"));
    m_settings->verify([this](const QString& failure) {
        if (m_ended)
            return;
        if (!failure.isEmpty()) {
            fail(tr("verifying the settings: %1").arg(failure));
            return;
        }
        test();
    });
}

void EolDriveRun::test()
{
    m_commLoss = std::make_unique<CommLossArm>(m_session);
    if (!m_commLoss->applies()) {
        runSteps();
        return;
    }
    setPhase(Phase::Test, tr("arming the communication-loss stop"));
    m_commLoss->arm([this](const QString& error) {
        if (m_ended)
            return;
        if (!error.isEmpty()) {
            fail(error);
            return;
        }
        runSteps();
    });
}

void EolDriveRun::runSteps()
{
    setPhase(Phase::Test, tr("testing"));
    m_steps = new EolStepRunner(m_session, m_run, m_position.steps, m_timing, this);
    connect(m_steps, &EolStepRunner::stepStarted, this, [this](int index, const QString& title) {
        setPhase(Phase::Test,
                 tr("step %1 of %2: %3").arg(index + 1).arg(m_position.steps.size()).arg(title));
    });
    connect(m_steps, &EolStepRunner::measured, this, [this](const Measurement& m) {
        m_measurements.append(m);
        emit measured(m);
    });
    connect(m_steps, &EolStepRunner::speedSampled, this, [this](double speed, const QString& unit) {
        emit speedSampled(m_position.machineNumber, speed, unit);
    });
    m_steps->start([this](const EolStepRunner::Result& r) {
        m_stopConfirmed = r.stopConfirmed;
        m_stopDetail = r.stopDetail;
        m_commLoss->disarm([this, r] {
            if (!r.ok) {
                fail(r.failure);
                return;
            }
            m_ok = true;
            finish();
        });
    });
}

void EolDriveRun::abort(const QString& reason)
{
    if (m_ended)
        return;
    if (m_steps && m_steps->isRunning()) {
        m_steps->abort(reason); // stops the motor; its result ends this run
        return;
    }
    if (m_settings && m_settings->isWriting()) {
        // A write and its read-back belong together: the restorer stops after it.
        m_settings->cancel();
        if (m_failure.isEmpty())
            m_failure = reason;
        return;
    }
    fail(reason);
}

void EolDriveRun::failStation(const QString& reason)
{
    if (!m_ended && m_failure.isEmpty())
        m_stationError = true;
    fail(reason);
}

void EolDriveRun::fail(const QString& reason)
{
    if (m_ended)
        return;
    if (m_failure.isEmpty())
        m_failure = reason;
    m_ok = false;
    finish();
}

void EolDriveRun::finish()
{
    if (m_ended)
        return;
    m_ended = true;
    if (m_settings)
        m_settings->drop(); // its answers from now on are dropped, as this run's are
    setPhase(Phase::Done, m_ok ? tr("passed") : m_failure);
    if (m_done) {
        auto done = std::move(m_done);
        m_done = nullptr;
        done();
    }
}

} // namespace opentop
