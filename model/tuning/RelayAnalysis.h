#pragma once

#include "tuning/TuningSample.h"

#include <QCoreApplication>
#include <QString>

namespace opentop {

// The Åström–Hägglund relay experiment read from its samples: the feedback oscillates around
// `setpoint` while the output switches by ±`relayAmplitude` (with `hysteresis` in feedback
// units); the ultimate gain is 4d / (π·√(a² − ε²)) and the ultimate period the mean period of
// the last full cycles. Needs at least `minCycles` cycles whose periods and amplitudes agree.
struct RelayAnalysis
{
    Q_DECLARE_TR_FUNCTIONS(opentop::RelayAnalysis)
public:
    bool ok = false;
    QString error;
    double ultimateGain = 0; // output units per feedback unit
    double periodMs = 0;
    double amplitude = 0; // half the feedback's peak-to-peak
    int cycles = 0;
    double spread = 0; // largest relative deviation of a period from the mean

    static RelayAnalysis analyse(const TuningSamples& samples, double setpoint,
                                 double relayAmplitude, double hysteresis, int minCycles = 3);
};

} // namespace opentop
