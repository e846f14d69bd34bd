#pragma once

#include "tuning/PidGains.h"
#include "tuning/TuningSample.h"

#include <QCoreApplication>
#include <QString>

namespace opentop {

struct TuningSpec;

// A first-order-plus-dead-time model of the speed loop's plant (output duty → feedback, both in
// register units), fitted to a relay experiment: with the static gain K and the ultimate point
// (Ku, Tu),  K·Ku = √(1 + (τω)²)  and  atan(τω) + θω = π  at ω = 2π/Tu. The experiment ran
// through the bus, so its loop held `busDelayMs` more dead time than the controller's own loop;
// the model leaves it out, which is what makes gains found over a slow line fit the drive.
struct PlantModel
{
    Q_DECLARE_TR_FUNCTIONS(opentop::PlantModel)
public:
    bool valid = false;
    QString error;
    double gain = 0; // feedback per output, register units
    double tauMs = 0;
    double deadMs = 0;

    static PlantModel fromRelay(double gain, double ultimateGain, double ultimatePeriodMs,
                                double busDelayMs, double minDeadMs);
    // The ultimate gain and period of this model in a loop of its own.
    bool ultimate(double* ku, double* tuMs) const;
    // The controller's loop (TuningSpec's form, its output limited to ±full scale) on this
    // model after a set point step from → to (register units), sampled every `sampleMs`.
    TuningSamples simulateStep(const PidGains& gains, const TuningSpec& spec, double from,
                               double to, double durationMs, double sampleMs) const;
};

} // namespace opentop
