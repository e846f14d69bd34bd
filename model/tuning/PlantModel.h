#pragma once

#include "model/tuning/PidGains.h"
#include "model/tuning/TuningSample.h"

#include <QCoreApplication>
#include <QString>

namespace opentop {

struct TuningSpec;

// A first-order-plus-dead-time model of the speed loop's plant (output duty → feedback, both in
// register units), fitted to a relay experiment: with the static gain K and the ultimate point
// (Ku, Tu),  K·Ku = √(1 + (τω)²)  and  atan(τω) + θω = π  at ω = 2π/Tu. The experiment ran
// through the bus, so its loop held `busDelayMs` more dead time than the controller's own loop;
// the model leaves it out (RelayAnalysis refuses a relay whose loop the bus dominated).
// The dead time sits on the measurement (the drive's speed gate), the lag on the shaft. The
// motor current follows the output's distance from what the shaft's speed needs,
// i = rest + c·(u − x/K), and the drive limits it: while limited the shaft accelerates no
// faster, whatever the controller asks, and the controller's integral keeps growing.
struct PlantModel
{
    Q_DECLARE_TR_FUNCTIONS(opentop::PlantModel)
public:
    bool valid = false;
    QString error;
    double gain = 0; // feedback per output, register units
    double tauMs = 0;
    double deadMs = 0;
    double currentPerOutput = 0; // c, A per output register unit; 0: current not modelled
    double restCurrent = 0;      // A at the operating point (friction, load)
    double currentLimit = 0;     // A; 0: none

    static PlantModel fromRelay(double gain, double ultimateGain, double ultimatePeriodMs,
                                double busDelayMs, double minDeadMs);
    // c from the current's jumps where the relay switched (±d, register units): the readings
    // just before and after a switch, the later one taken back to the switch with the lag τ.
    // Reversals are assumed (the larger jump): c errs high, the limit comes early.
    static double currentPerOutputOf(const TuningSamples& relay, double outputScale, double d,
                                     double tauMs);
    // The ultimate gain and period of this model in a loop of its own.
    bool ultimate(double* ku, double* tuMs) const;
    // The controller's loop (TuningSpec's form, its output limited to ±full scale) on this
    // model after a set point step from → to (register units), sampled every `sampleMs`; each
    // sample's current is the model's.
    TuningSamples simulateStep(const PidGains& gains, const TuningSpec& spec, double from,
                               double to, double durationMs, double sampleMs) const;
};

} // namespace opentop
