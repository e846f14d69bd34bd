#pragma once

#include "model/tuning/GainDesign.h"
#include "model/tuning/PidGains.h"
#include "model/tuning/PlantModel.h"
#include "model/tuning/RelayAnalysis.h"
#include "model/tuning/StepMetrics.h"
#include "model/tuning/TuningRules.h"
#include "model/tuning/TuningSpec.h"

#include <QElapsedTimer>
#include <QObject>
#include <QStringList>
#include <functional>
#include <memory>
#include <optional>

namespace opentop {

class DeviceSession;
struct ParamValue;
class RelayAutotune;
class StepTest;
class TuningDrive;

// Speed-loop tests on a drive that has a TuningSpec, over its DeviceSession: a step test (from
// speed A to B in the present closed-loop mode, recorded as fast as the line allows) and the
// relay autotune (in the open-loop mode, the output switched around an operating speed). Each
// test is started only by an explicit call, keeps the speed and current within its limits
// (beyond them it stops the motor at once), runs with the communication-loss braking time set,
// and ends by stopping the motor, confirming the stop, and restoring the speed mode and the
// communication-loss time it found. Gains are written only by writeGains() and stored only by
// storeGains(). The facade of the tests: the step test is StepTest, the autotune RelayAutotune,
// what both do on the drive (and their common first and last states) TuningDrive.
class TuningRunner : public QObject
{
    Q_OBJECT
public:
    struct Limits
    {
        double maxSpeed = 0;   // feedback units; beyond: stop
        double maxCurrent = 0; // A; beyond: stop
        double commLossS = 0.5;
        int stopTimeoutMs = 5000;
    };
    struct StepPlan
    {
        double from = 0; // engineering units of the closed-loop mode's speed command
        double to = 0;
        int settleMs = 3000; // longest wait at `from` before the step
        int recordMs = 1500;
    };
    struct RelayPlan
    {
        double speed = 0;      // operating speed, feedback units
        double amplitude = 10; // output swing, % of full duty
        double hysteresis = 0; // feedback units; 0: 1 % of the speed
        int maxMs = 10000;     // the relay's longest run
        int cycles = 4;        // steady cycles wanted
        TuningRules::Rule rule = TuningRules::Rule::Medium;
    };
    struct Result
    {
        bool ok = false;
        bool aborted = false; // stopped by a limit, cancel or a failure
        QString error;
        QString advice; // what to change when the autotune's result was refused
        bool stopConfirmed = true;
        QString stopDetail;
        TuningSamples samples;
        PidGains gains; // in the drive during the test
        QString speedUnit;
        // Step test
        double from = 0, to = 0;
        StepMetrics metrics;
        // Autotune
        double plantGain = 0; // register units
        double busDelayMs = 0;
        double readingMs = 0; // a plain reading's interval (no switch between), measured
        RelayAnalysis relay;
        PlantModel plant;
        double ultimateGain = 0; // of the drive's own loop (register units)
        double ultimatePeriodMs = 0;
        PidGains proposal;
        double kpScale = 1; // GainDesign: of the rule's Kp and Ti
        double tiScale = 1;
        TuningSamples predicted; // the proposal on the model, from → to as a step test would
        StepMetrics predictedMetrics;
    };
    // The drive's own loop must oscillate slower than this many plain readings (2 is Nyquist's
    // limit), or the step after Accept could not show whether the gains work.
    static constexpr double kMinReadingsPerLoopPeriod = 2.5;
    using Done = std::function<void(const Result&)>;
    using GainsDone = std::function<void(bool ok, const PidGains& gains, const QString& error)>;

    TuningRunner(DeviceSession* session, const TuningSpec& spec, QObject* parent = nullptr);
    ~TuningRunner() override;
    const TuningSpec& spec() const { return m_spec; }
    DeviceSession* session() const { return m_session; }

    void setLimits(const Limits& limits);
    const Limits& limits() const;
    // The time samples are stamped with, in ms (tests on a simulated clock); a steady clock
    // by default.
    void setClock(std::function<double()> nowMs);

    // Only one test at a time; `done` runs once, never before the call returns.
    void startStep(const StepPlan& plan, Done done);
    void startAutotune(const RelayPlan& plan, Done done);
    void cancel();
    bool isRunning() const;
    // The named states the present or last test went through, in order (tests, the log).
    const QStringList& stateTrail() const;

    void readGains(GainsDone done);
    // Writes the gains (temporary in the drive until stored) and reads them back.
    void writeGains(const PidGains& gains, GainsDone done);
    void storeGains(std::function<void(bool ok, const QString& error)> done);

signals:
    void sampled(const opentop::TuningSample& sample);
    void phase(const QString& text);

private:
    void writeGainsFrom(const PidGains& gains, int k, GainsDone done);

    DeviceSession* m_session;
    TuningSpec m_spec;
    // Destroyed in reverse: the tests before the drive, whose end stops a motor mid-test.
    std::unique_ptr<TuningDrive> m_drive;
    std::unique_ptr<StepTest> m_step;
    std::unique_ptr<RelayAutotune> m_relay;
};

} // namespace opentop
