#pragma once

#include "model/tuning/TuningRunner.h"

#include <QCoreApplication>
#include <QStringList>

namespace opentop {

// After Accept: the step measured with the accepted gains against the step the model predicted
// for them. It fails when the step was not measured to its end (a limit, a failure, a cancel),
// when the speed does not settle within the record (±2 % of the step), or when it overshoots
// more than kOvershootMargin points beyond the prediction. A failed or missing check keeps the
// gains from being stored unless the user overrides it (docs/tuning.md, "The check after
// Accept").
struct TuningVerdict
{
    Q_DECLARE_TR_FUNCTIONS(opentop::TuningVerdict)
public:
    bool measured = false; // a step with the accepted gains ran to its end
    bool passed = false;
    QStringList findings; // what failed, each a sentence for people
    double overshootPercent = 0;
    double predictedOvershootPercent = 0;
    std::optional<double> settlingMs;
    std::optional<double> predictedSettlingMs;
    double peakCurrent = 0;

    static constexpr double kOvershootMargin = 10; // percentage points of the step

    static TuningVerdict judge(const TuningRunner::Result& step, const StepMetrics& predicted);
    static TuningVerdict notMeasured(const QString& why);
    // One paragraph: what was measured against the prediction, and what failed.
    QString text() const;
};

} // namespace opentop
