#include "model/tuning/TuningVerdict.h"

#include <QLocale>

namespace opentop {

namespace {

QString ms(const std::optional<double>& v)
{
    return v ? TuningVerdict::tr("%1 ms").arg(*v, 0, 'f', 0)
             : TuningVerdict::tr("none within the record");
}

} // namespace

TuningVerdict TuningVerdict::notMeasured(const QString& why)
{
    TuningVerdict v;
    v.findings << tr("no step was measured to its end with these gains: %1").arg(why);
    return v;
}

TuningVerdict TuningVerdict::judge(const TuningRunner::Result& step, const StepMetrics& predicted)
{
    TuningVerdict v;
    v.predictedOvershootPercent = predicted.overshootPercent;
    v.predictedSettlingMs = predicted.settlingMs;
    if (!step.ok || !step.metrics.valid) {
        const QString why = step.error.isEmpty() ? step.metrics.error : step.error;
        v = notMeasured(why);
        v.predictedOvershootPercent = predicted.overshootPercent;
        v.predictedSettlingMs = predicted.settlingMs;
        // What the step showed before it ended is still worth naming.
        const StepMetrics partial = StepMetrics::measure(step.samples, step.from, step.to);
        v.overshootPercent = partial.valid ? partial.overshootPercent : 0;
        v.peakCurrent = partial.valid ? partial.peakCurrent : 0;
        return v;
    }
    const StepMetrics& m = step.metrics;
    v.measured = true;
    v.overshootPercent = m.overshootPercent;
    v.settlingMs = m.settlingMs;
    v.peakCurrent = m.peakCurrent;
    if (!m.settlingMs)
        v.findings << tr("the speed did not settle within %1 ms (±2 % of the step)")
                          .arg(m.recordMs, 0, 'f', 0);
    if (m.overshootPercent > predicted.overshootPercent + kOvershootMargin)
        v.findings << tr("it overshot by %1 % where %2 % was predicted (at most %3 points more "
                         "are accepted)")
                          .arg(m.overshootPercent, 0, 'f', 1)
                          .arg(predicted.overshootPercent, 0, 'f', 1)
                          .arg(kOvershootMargin);
    v.passed = v.findings.isEmpty();
    return v;
}

QString TuningVerdict::text() const
{
    QString text = measured ? tr("Measured: overshoot %1 % (predicted %2 %), settling time %3 "
                                 "(predicted %4), peak current %5 A.")
                                  .arg(overshootPercent, 0, 'f', 1)
                                  .arg(predictedOvershootPercent, 0, 'f', 1)
                                  .arg(ms(settlingMs), ms(predictedSettlingMs))
                                  .arg(peakCurrent, 0, 'f', 1)
                            : QString();
    if (!findings.isEmpty()) {
        if (!text.isEmpty())
            text += QLatin1Char(' ');
        text += tr("Check failed: %1.").arg(findings.join(QStringLiteral("; ")));
    }
    return text;
}

} // namespace opentop
