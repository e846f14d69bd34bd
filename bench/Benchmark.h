#pragma once

#include <QString>

namespace opentop {

class BenchReport;

// What every benchmark gets: where the programs are and how long to measure each figure.
struct BenchEnvironment
{
    QString binDir;         // opentop, opentop-cli and opentop-sim
    double seconds = 3;     // measuring time per throughput figure
    double guiSeconds = 30; // per GUI load case, after its warm-up
};

// One named benchmark of opentop-bench. run() adds figures to the report as it measures them
// and returns false with *error when it could not measure (a wrong result counts).
class Benchmark
{
public:
    virtual ~Benchmark() = default;
    virtual QString name() const = 0;
    virtual QString description() const = 0;
    virtual bool run(const BenchEnvironment& env, BenchReport& report, QString* error) = 0;
};

} // namespace opentop
