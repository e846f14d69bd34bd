#pragma once

#include "model/tuning/TuningRunner.h"

#include <QCoreApplication>

namespace opentop {

class TuningDrive;

// The relay autotune's own states, between TuningDrive's Prepare/SetCommLoss and its exit:
// OpenLoop (the plan checked, the open-loop mode set, a first output guessed from the speed
// command's range), Estimate (an output held until the speed no longer moves: the plant's
// gain and the output for the operating speed; entered a second time when the first guess was
// off by more than 1 % of full output), Relay (the output switched ± the amplitude around it
// as the speed crosses the operating speed, until the oscillation is steady or the relay's
// time is up) and Conclude (RelayTuning: the model and the proposal, or the refusal).
class RelayAutotune
{
    Q_DECLARE_TR_FUNCTIONS(opentop::RelayAutotune)
public:
    enum State
    {
        OpenLoop = 20,
        Estimate,
        Relay,
        Conclude,
    };

    // Adds its states to the drive's.
    explicit RelayAutotune(TuningDrive* drive);

    void start(const TuningRunner::RelayPlan& plan, TuningRunner::Done done);

private:
    void openLoop();
    double firstOutput() const;
    void estimate();
    void hold();
    void held(double y);
    void relay();
    void swing();
    void conclude();

    TuningDrive* m_drive;
    TuningRunner::RelayPlan m_plan;
    double m_openScale = 1;   // engineering per raw of the open-loop (duty) command
    double m_plantGain = 0;   // feedback engineering per output raw
    double m_restCurrent = 0; // A, at the last hold before the relay
    // Estimate: which hold, its output and, at the second, the first's output and speed.
    int m_hold = 0;
    double m_u = 0;
    double m_u1 = 0;
    double m_y1 = 0;
    // Relay: the output it switches around, the swing, the hysteresis and the side it is on.
    double m_u0 = 0;
    double m_d = 0;
    double m_h = 0;
    bool m_high = false;
};

} // namespace opentop
