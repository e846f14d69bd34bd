#pragma once

#include "bench/Benchmark.h"

namespace opentop {

// The `opentop` program monitoring drives that opentop-sim simulates behind a Modbus TCP
// gateway, motors turning, with the bus overview and every drive's trend open
// (--monitor-all): 16 drives at 10 Hz and 64 drives at 2 Hz. CPU time over wall time at steady
// state (the trends' window full), and resident memory, read from /proc.
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
