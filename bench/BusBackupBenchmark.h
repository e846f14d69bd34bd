#pragma once

#include "bench/Benchmark.h"

namespace opentop {

// `opentop-cli backup` of a 32-drive bus at 115200 bit/s with wire timing on a half-duplex
// simulated line, run as the program users run: once for known machine numbers, once with
// --all (a scan first). Against the wire's own need for the backup's read requests.
class BusBackupBenchmark : public Benchmark
{
public:
    QString name() const override { return QStringLiteral("bus-backup"); }
    QString description() const override;
    bool run(const BenchEnvironment& env, BenchReport& report, QString* error) override;
};

} // namespace opentop
