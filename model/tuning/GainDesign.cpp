#include "model/tuning/GainDesign.h"

#include "model/tuning/TuningSpec.h"

namespace opentop {

namespace {

// Kp lowered first, then Ti lengthened: the first pair that passes is the least detuned.
const double kKpScales[] = {1, 0.8, 0.63, 0.5, 0.4, 0.32, 0.25, 0.2, 0.16, 0.125, 0.1};
const double kTiScales[] = {1, 1.5, 2, 3, 4, 6, 10, 16};

} // namespace

GainDesign GainDesign::choose(const PlantModel& model, TuningRules::Rule rule,
                              const TuningSpec& spec, int dPeriodMs, double from, double to,
                              double deadUncertaintyMs)
{
    GainDesign d;
    if (!model.ultimate(&d.ultimateGain, &d.ultimatePeriodMs)) {
        d.error = model.error.isEmpty() ? tr("the model has no ultimate point") : model.error;
        return d;
    }
    PlantModel uncertain = model;
    uncertain.deadMs += std::max(0.0, deadUncertaintyMs);
    uncertain.gain *= kMoreGain;
    uncertain.currentPerOutput *= 2;
    const double bound = TuningRules::overshootBound(rule);
    const TuningRules::Continuous start =
        TuningRules::continuous(rule, d.ultimateGain, d.ultimatePeriodMs);
    for (double kpScale : kKpScales) {
        for (double tiScale : kTiScales) {
            TuningRules::Continuous c = start;
            c.kp *= kpScale;
            c.tiMs *= tiScale;
            const PidGains g = TuningRules::toController(c, spec, dPeriodMs);
            const TuningSamples nominal = model.simulateStep(g, spec, from, to, kRecordMs, 5);
            const StepMetrics m = StepMetrics::measure(nominal, from, to);
            if (!m.valid || !m.settlingMs || *m.settlingMs > kRecordMs * 2 / 3 ||
                m.overshootPercent > bound)
                continue;
            const StepMetrics u = StepMetrics::measure(
                uncertain.simulateStep(g, spec, from, to, kRecordMs, 5), from, to);
            if (!u.valid || !u.settlingMs || u.overshootPercent > bound + kExtraOvershoot)
                continue;
            d.ok = true;
            d.gains = g;
            d.kpScale = kpScale;
            d.tiScale = tiScale;
            d.predicted = nominal;
            d.metrics = m;
            return d;
        }
    }
    d.error = tr("no gains from the %1 rule settle within %2 ms with at most %3 % overshoot on "
                 "the motor's model, even with P at a tenth of the rule's")
                  .arg(TuningRules::title(rule))
                  .arg(kRecordMs * 2 / 3)
                  .arg(bound);
    d.advice = tr("Try a rule that allows more overshoot or a smaller step (a lower operating "
                  "speed), or raise the drive's current limit if the motor allows it.");
    return d;
}

} // namespace opentop
