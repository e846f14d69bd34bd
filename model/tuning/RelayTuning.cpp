#include "model/tuning/RelayTuning.h"

#include <algorithm>

namespace opentop {

void RelayTuning::conclude(const TuningSpec& spec, const Input& in, TuningRunner::Result* r)
{
    const TuningSamples& s = r->samples;
    r->ok = false;
    r->relay = in.relay;
    const auto refuse = [r](const QString& why, const QString& advice) {
        r->error = why;
        r->advice = advice;
    };
    if (!in.relay.ok) {
        refuse(in.relay.error, in.relay.advice);
        return;
    }
    // The bus's part of the loop's dead time: a reading's age when the output switches on it.
    r->busDelayMs = s.size() > 1 ? (s.last().tMs - s.first().tMs) / (s.size() - 1) : 0;
    // Register units: the controller's error is in raw command units.
    const double scale = in.closedScale > 0 ? in.closedScale : 1;
    r->plantGain = in.plantGain;
    r->plant = PlantModel::fromRelay(in.plantGain / scale, in.relay.ultimateGain * scale,
                                     in.relay.periodMs, r->busDelayMs, spec.periodMs);
    if (!r->plant.valid) {
        refuse(r->plant.error, tr("Raise the relay amplitude."));
        return;
    }
    r->plant.currentPerOutput =
        PlantModel::currentPerOutputOf(s, in.openScale, in.d, r->plant.tauMs);
    r->plant.restCurrent = in.restCurrent;
    r->plant.currentLimit = in.currentLimit;
    QVector<double> plain; // the step after Accept reads this often
    for (int k = 1; k < s.size(); ++k) {
        if (s[k].command == s[k - 1].command)
            plain << s[k].tMs - s[k - 1].tMs;
    }
    std::sort(plain.begin(), plain.end());
    r->readingMs = plain.isEmpty() ? r->busDelayMs : plain[plain.size() / 2];
    const double from = in.speed / 2;
    const GainDesign design = GainDesign::choose(r->plant, in.rule, spec, r->gains.dPeriodMs,
                                                 from / scale, in.speed / scale, r->busDelayMs);
    r->ultimateGain = design.ultimateGain;
    r->ultimatePeriodMs = design.ultimatePeriodMs;
    const double minPeriod = TuningRunner::kMinReadingsPerLoopPeriod * r->readingMs;
    if (r->ultimatePeriodMs > 0 && r->ultimatePeriodMs < minPeriod) {
        refuse(tr("the drive's own loop, as the model extrapolates it, would oscillate with a "
                  "period of %1 ms, under %2 readings (one every %3 ms): the step after Accept "
                  "could not show whether the gains work")
                   .arg(r->ultimatePeriodMs, 0, 'f', 1)
                   .arg(TuningRunner::kMinReadingsPerLoopPeriod)
                   .arg(r->readingMs, 0, 'f', 1),
               tr("Raise the line rate (115200 bit/s if every drive on the bus allows it) or "
                  "stop polling other drives on this bus during the test."));
        return;
    }
    if (!design.ok) {
        refuse(design.error, design.advice);
        return;
    }
    r->proposal = design.gains;
    r->kpScale = design.kpScale;
    r->tiScale = design.tiScale;
    r->predicted = design.predicted;
    for (TuningSample& p : r->predicted) {
        p.speed *= scale;
        p.command = in.speed;
    }
    r->predictedMetrics = StepMetrics::measure(r->predicted, from, in.speed);
    r->ok = true;
}

} // namespace opentop
