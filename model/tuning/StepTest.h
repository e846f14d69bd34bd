#pragma once

#include "model/tuning/TuningRunner.h"

#include <QCoreApplication>

namespace opentop {

class TuningDrive;

// The step test's own states, between TuningDrive's Prepare/SetCommLoss and its exit: Approach
// (the plan checked, the motor run to `from` until it has stayed near it for 300 ms or the
// settle time is up) and Record (the samples so far moved to negative times, the command
// stepped to `to`, readings as fast as the line allows for the record time, then the metrics).
// A step from 0 goes straight from Approach to Record.
class StepTest
{
    Q_DECLARE_TR_FUNCTIONS(opentop::StepTest)
public:
    enum State
    {
        Approach = 10,
        Record,
    };

    // Adds its states to the drive's.
    explicit StepTest(TuningDrive* drive);

    void start(const TuningRunner::StepPlan& plan, TuningRunner::Done done);

private:
    void approach();
    void awaitFrom();
    void record();
    void recordReading();

    TuningDrive* m_drive;
    TuningRunner::StepPlan m_plan;
    double m_settledSince = -1; // ms, near `from` since then (-1: not near)
};

} // namespace opentop
