#pragma once

#include "model/eol/EolStepRunner.h"
#include "model/eol/RecipeTypes.h"
#include "model/eol/UnitRecord.h"
#include "model/eol/VariantDecision.h"

#include <QHash>
#include <QObject>
#include <functional>
#include <memory>

namespace opentop {

class CommLossArm;
class DeviceSession;
struct DeviceInfo;
class EolSettingsWriter;
class ModbusClient;
class ProfileRegistry;
class RunControl;

// One drive of a unit through the end-of-line run: identify it, check that it is an allowed
// model, variant and firmware, write only the recipe's settings that differ and read every one
// back once more (EolSettingsWriter), then run its steps (EolStepRunner). The first failure
// ends it; a drive whose motor may be turning is stopped first.
class EolDriveRun : public QObject
{
    Q_OBJECT
public:
    enum class Phase
    {
        Identify,
        Write,
        Verify,
        Test,
        Done
    };

    EolDriveRun(ModbusClient* client, const ProfileRegistry& registry, RunControl* run,
                const RecipePosition& position, int index, QHash<QString, double> unitValues,
                const EolStepRunner::Timing& timing, QObject* parent = nullptr);
    ~EolDriveRun() override;

    // The variant the person running the unit gave for this position (may be empty), and who
    // that is: VariantDecision weighs it against what the drive reports or the probe proves.
    void setVariantEvidence(const QString& asserted, const QString& operatorName);

    // `done` runs once, never before start() returns.
    void start(std::function<void()> done);
    // Ends the run with `reason` (the motor stopped first when it may be turning).
    void abort(const QString& reason);

    int machineNumber() const { return m_position.machineNumber; }
    QString title() const; // "position 1 (machine number 1)"
    Phase phase() const { return m_phase; }
    bool ok() const { return m_ok; }
    QString failure() const { return m_failure; }
    // The failure is the station's, not the unit's (no answer, a motor already turning, an
    // alarm latched before anything was written): no verdict on the unit.
    bool stationError() const { return m_stationError; }
    // An alarm was active before the test: a reset may let the unit be tested again.
    bool alarmLatched() const { return m_alarmLatched; }
    // The failure is the drive's identity (no drive, another family, a variant or firmware
    // the recipe does not allow, a variant not proven): a station error, not the unit's test.
    bool identityError() const { return m_identityError; }
    bool stopConfirmed() const { return m_stopConfirmed; }
    QString stopDetail() const { return m_stopDetail; }
    const UnitDrive& drive() const { return m_drive; }
    const QVector<WrittenValue>& writtenValues() const;
    const QVector<Measurement>& measurements() const { return m_measurements; }

signals:
    void phaseChanged(int machineNumber, opentop::EolDriveRun::Phase phase, const QString& text);
    void measured(const opentop::Measurement& measurement);
    void speedSampled(int machineNumber, double speed, const QString& unit);

private:
    void identified(const DeviceInfo& info);
    void checkStopped();
    void checkVariant();
    void variantKnown(const VariantDecision::Decision& decision);
    void failIdentity(const QString& reason);
    void write();
    void verify();
    void test();
    void runSteps();
    void setPhase(Phase phase, const QString& text);
    void fail(const QString& reason);
    void failStation(const QString& reason);
    void finish();

    ModbusClient* m_client;
    const ProfileRegistry& m_registry;
    RunControl* m_run;
    RecipePosition m_position;
    int m_index;
    QHash<QString, double> m_unitValues;
    EolStepRunner::Timing m_timing;
    std::function<void()> m_done;
    Phase m_phase = Phase::Identify;
    bool m_ok = false;
    bool m_identityError = false;
    QString m_reportedVariant;
    QString m_assertedVariant;
    QString m_operatorName;
    bool m_ended = false;
    QString m_failure;
    bool m_stationError = false;
    bool m_alarmLatched = false;
    bool m_stopConfirmed = true;
    QString m_stopDetail;
    UnitDrive m_drive;
    QVector<Measurement> m_measurements;
    DeviceSession* m_session = nullptr;
    std::unique_ptr<CommLossArm> m_commLoss;
    EolSettingsWriter* m_settings = nullptr; // once the variant is known
    EolStepRunner* m_steps = nullptr;
};

} // namespace opentop

Q_DECLARE_METATYPE(opentop::EolDriveRun::Phase)
