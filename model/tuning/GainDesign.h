#pragma once

#include "model/tuning/PidGains.h"
#include "model/tuning/PlantModel.h"
#include "model/tuning/StepMetrics.h"
#include "model/tuning/TuningRules.h"

#include <QCoreApplication>
#include <QString>

namespace opentop {

struct TuningSpec;

// The gains a rule proposes for a plant model, checked on the model before they are offered.
// The rule gives the start: its Kp, Ti, Td from the ultimate point of the drive's own loop.
// Ziegler–Nichols assumes a linear plant; a drive that limits its current is not one, and its
// integral winds up while the current is limited, so the rule's gains may overshoot far beyond
// its promise. From the start Kp is lowered and Ti lengthened, step by step, until the
// predicted step from → to (the one the check after Accept measures) overshoots no more than
// the rule's bound and settles within two thirds of the record, and, on a model with the
// uncertainty added (the bus's delay as more dead time, 20 % more gain, the current limit at
// half), still settles and overshoots at most 10 points more. docs/tuning.md has the reasons.
struct GainDesign
{
    Q_DECLARE_TR_FUNCTIONS(opentop::GainDesign)
public:
    bool ok = false;
    QString error;
    QString advice;
    PidGains gains;
    double ultimateGain = 0; // of the drive's own loop on the model
    double ultimatePeriodMs = 0;
    double kpScale = 1;      // of the rule's Kp
    double tiScale = 1;      // of the rule's Ti
    TuningSamples predicted; // register units
    StepMetrics metrics;     // of `predicted`

    static constexpr double kRecordMs = 1500;
    static constexpr double kExtraOvershoot = 10; // points, on the uncertain model
    static constexpr double kMoreGain = 1.2;

    static GainDesign choose(const PlantModel& model, TuningRules::Rule rule,
                             const TuningSpec& spec, int dPeriodMs, double from, double to,
                             double deadUncertaintyMs);
};

} // namespace opentop
