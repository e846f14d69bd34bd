#pragma once

#include "model/tuning/TuningRunner.h"

#include <QCoreApplication>

namespace opentop {

// From a relay experiment's record to the proposal, or to the reason there is none: the
// relay's own checks (RelayAnalysis), the plant model with the bus's delay left out and the
// motor current (PlantModel), whether the bus could watch the drive's own loop, and the gains
// checked on the model (GainDesign). Fills the autotune's part of a TuningRunner::Result: on a
// refusal `ok` is false, `error` says why and `advice` what to change.
struct RelayTuning
{
    Q_DECLARE_TR_FUNCTIONS(opentop::RelayTuning)
public:
    struct Input
    {
        RelayAnalysis relay;
        double plantGain = 0;    // feedback engineering per output raw, from the holds
        double closedScale = 1;  // engineering per raw of the closed-loop speed command
        double openScale = 1;    // engineering per raw of the open-loop (duty) command
        double d = 0;            // the relay's swing, output raw
        double restCurrent = 0;  // A at the operating point
        double currentLimit = 0; // A, the drive's (0: unknown)
        double speed = 0;        // the operating speed, feedback engineering
        TuningRules::Rule rule = TuningRules::Rule::Medium;
    };

    static void conclude(const TuningSpec& spec, const Input& in, TuningRunner::Result* r);
};

} // namespace opentop
