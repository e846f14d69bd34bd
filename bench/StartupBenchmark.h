#pragma once

#include "bench/Benchmark.h"

namespace opentop {

// `opentop --sim ... --startup-probe` from the process start until the window has painted the
// simulated bus's drives, five times; the median is judged.
class StartupBenchmark : public Benchmark
{
public:
    QString name() const override { return QStringLiteral("startup"); }
    QString description() const override;
    bool run(const BenchEnvironment& env, BenchReport& report, QString* error) override;
};

} // namespace opentop
