#include "model/tuning/StepTest.h"

#include "model/tuning/TuningDrive.h"

#include <algorithm>
#include <cmath>

namespace opentop {

namespace {

constexpr int kSettledForMs = 300; // at `from` this long before the step

} // namespace

StepTest::StepTest(TuningDrive* drive)
    : m_drive(drive)
{
    RunnerStates& states = drive->states();
    states.add(Approach, "approach", [this] { approach(); });
    states.add(Record, "record", [this] { record(); });
}

void StepTest::start(const TuningRunner::StepPlan& plan, TuningRunner::Done done)
{
    if (m_drive->refuseIfRunning(done))
        return;
    m_plan = plan;
    m_settledSince = -1;
    m_drive->begin(std::move(done), Approach);
}

void StepTest::approach()
{
    TuningRunner::Result& r = m_drive->result();
    r.from = m_plan.from;
    r.to = m_plan.to;
    if (m_plan.from < 0 || m_plan.to < 0 || m_plan.from == m_plan.to) {
        m_drive->fail(tr("a step test runs forward from one speed to another: from and to must "
                         "differ and be 0 or more"),
                      false);
        return;
    }
    const double maxSpeed = m_drive->limits().maxSpeed;
    for (double v : {m_plan.from, m_plan.to}) {
        if (maxSpeed > 0 && v > maxSpeed) {
            m_drive->fail(tr("%1 %2 is beyond the test's speed limit %3 %2")
                              .arg(v)
                              .arg(r.speedUnit)
                              .arg(maxSpeed),
                          false);
            return;
        }
    }
    m_drive->announce(tr("Running to %1 %2").arg(m_plan.from).arg(r.speedUnit));
    if (m_plan.from == 0) {
        m_drive->states().go(Record);
        return;
    }
    m_drive->command(m_plan.from, [this] { awaitFrom(); });
}

// One reading of the approach; the next one at once until the motor is settled at `from`.
void StepTest::awaitFrom()
{
    m_drive->poll([this](const TuningSample& sample) {
        TuningSample s = sample;
        s.command = m_plan.from;
        m_drive->record(s);
        const double band = std::max(StepMetrics::kSettlingBand * std::abs(m_plan.to - m_plan.from),
                                     m_drive->closedScale());
        const bool near = std::abs(s.speed - m_plan.from) <= band;
        m_settledSince = near ? (m_settledSince < 0 ? s.tMs : m_settledSince) : -1;
        if ((near && s.tMs - m_settledSince >= kSettledForMs) || s.tMs >= m_plan.settleMs) {
            m_drive->states().go(Record);
            return;
        }
        awaitFrom();
    });
}

void StepTest::record()
{
    const double now = m_drive->nowMs();
    for (TuningSample& s : m_drive->result().samples)
        s.tMs -= now - m_drive->reference(); // the approach before the step: negative times
    m_drive->setReference(now);
    m_drive->announce(tr("Step to %1 %2").arg(m_plan.to).arg(m_drive->result().speedUnit));
    m_drive->command(m_plan.to, [this] { recordReading(); });
}

// One reading of the record; the next one at once until the record time is up.
void StepTest::recordReading()
{
    m_drive->poll([this](const TuningSample& sample) {
        TuningSample s = sample;
        s.command = m_plan.to;
        m_drive->record(s);
        if (s.tMs < m_plan.recordMs) {
            recordReading();
            return;
        }
        TuningRunner::Result& r = m_drive->result();
        r.metrics = StepMetrics::measure(r.samples, m_plan.from, m_plan.to);
        r.ok = r.metrics.valid;
        r.error = r.metrics.error;
        m_drive->finish();
    });
}

} // namespace opentop
