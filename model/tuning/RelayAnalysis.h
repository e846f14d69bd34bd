#pragma once

#include "model/tuning/TuningSample.h"

#include <QCoreApplication>
#include <QString>

namespace opentop {

// The Åström–Hägglund relay experiment read from its samples: the feedback oscillates around
// `setpoint` while the output switches by ±`relayAmplitude` (with `hysteresis` in feedback
// units); the ultimate gain is 4d / (π·√(a² − ε²)) and the ultimate period the mean period of
// the last full cycles. The result is usable only when the oscillation is steady (at least
// `minCycles` cycles whose periods and amplitudes agree), seen by enough readings to show the
// motor rather than the bus, and even on both sides of the set point; otherwise `error` says
// why and `advice` what to change (docs/tuning.md, "When a relay result is refused").
struct RelayAnalysis
{
    Q_DECLARE_TR_FUNCTIONS(opentop::RelayAnalysis)
public:
    bool steady = false;   // enough cycles, their periods and amplitudes agree
    bool busPaced = false; // enough cycles, too few readings in each: more will not help
    bool ok = false;       // steady and every other check passed
    QString error;
    QString advice;
    double ultimateGain = 0; // output units per feedback unit
    double periodMs = 0;
    double amplitude = 0; // half the feedback's peak-to-peak
    int cycles = 0;
    double periodSpread = 0;    // largest relative deviation of a cycle's period from the mean
    double amplitudeSpread = 0; // the same for the amplitudes
    double asymmetry = 0;       // |time above − time below the set point| / period, mean
    double readingMs = 0;       // mean time between readings over the cycles: what the bus gave
    double readingsPerPeriod = 0;

    static constexpr double kMaxPeriodSpread = 0.15;
    static constexpr double kMaxAmplitudeSpread = 0.20;
    static constexpr double kMaxAsymmetry = 0.30;
    // A relay the bus paces switches at every reading or every second one: 2 or 4 readings per
    // period, whatever the motor. From 6 on the period is the motor's, and its peaks are seen
    // within 1 − cos(π/6) = 13 % (GainDesign's margin covers that).
    static constexpr double kMinReadingsPerPeriod = 5;

    static RelayAnalysis analyse(const TuningSamples& samples, double setpoint,
                                 double relayAmplitude, double hysteresis, int minCycles = 3);
};

} // namespace opentop
