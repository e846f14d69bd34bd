#pragma once

#include "bench/Benchmark.h"

namespace opentop {

// One unit of a DBU200 product through the end-of-line run (EolRun: identify, write what
// differs, read back, test), for one drive and for eight on one bus, each on its own
// simulator with wire timing at 19200 bit/s. The drives run concurrently, so eight should take
// far less than eight times one; the goal is at most twice.
class EolBenchmark : public Benchmark
{
public:
    QString name() const override { return QStringLiteral("eol"); }
    QString description() const override;
    bool run(const BenchEnvironment& env, BenchReport& report, QString* error) override;
};

} // namespace opentop
