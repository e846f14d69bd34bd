#pragma once

#include "model/tuning/TuningSample.h"

#include <QCoreApplication>
#include <QString>
#include <optional>

namespace opentop {

// What a step response shows, measured from the samples after a set point change `from` →
// `to` at t = 0 (TuningSample::tMs): rise time 10–90 % of the step, overshoot beyond `to` in
// percent of the step, settling time into and staying within ±2 % of the step (for at least
// 15 % of the record, so a swing through the band as the record ends is not "settled"),
// steady-state error (mean of the last quarter of the record minus `to`) and peak current.
struct StepMetrics
{
    Q_DECLARE_TR_FUNCTIONS(opentop::StepMetrics)
public:
    bool valid = false;
    QString error;
    // None: never reached 90 %, or never below 10 % (the speed was not at `from` at the step).
    std::optional<double> riseMs;
    double overshootPercent = 0;      // 0 when it never went beyond `to`
    std::optional<double> settlingMs; // none: not settled within the record
    double steadyStateError = 0;      // speed units, signed
    double peakCurrent = 0;
    double recordMs = 0;

    static StepMetrics measure(const TuningSamples& samples, double from, double to);
    static constexpr double kSettlingBand = 0.02;
    // Settled only if it then stays in the band this share of the record and these readings.
    static constexpr double kSettledHoldShare = 0.15;
    static constexpr int kSettledReadings = 3;
};

} // namespace opentop
