#pragma once

#include "Benchmark.h"

namespace opentop {

// The `opentop` program monitoring drives simulated in its own process (--sim; the figures
// include the simulation), with the bus overview and every
// drive's trend open (--monitor-all): 16 drives at 10 Hz and 64 drives at 2 Hz. CPU time over
// wall time after a warm-up, and resident memory, read from /proc.
class GuiBenchmark : public Benchmark
{
public:
    QString name() const override { return QStringLiteral("gui"); }
    QString description() const override;
    bool run(const BenchEnvironment& env, BenchReport& report, QString* error) override;

private:
    bool runCase(const BenchEnvironment& env, int drives, int pollMs, bool goals,
                 BenchReport& report, QString* error);
};

} // namespace opentop
