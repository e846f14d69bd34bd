#pragma once

#include "model/tuning/TuningRunner.h"

#include <QColor>
#include <QString>

namespace opentop {

// One curve set on the tuning page: a measured step test, or the step an autotune's model
// predicts for its proposal (drawn dashed). Runs are compared by overlaying them.
struct TuningRun
{
    enum class Kind
    {
        Step,
        Prediction
    };
    int id = 0;
    Kind kind = Kind::Step;
    QString title; // "Run 2: 0 → 500 1/s"
    PidGains gains;
    TuningRunner::Result result; // samples (predictions: result.samples too), metrics, unit
    QColor color;
    bool visible = true;
    bool live = false; // still recording

    bool isPrediction() const { return kind == Kind::Prediction; }
};

} // namespace opentop
