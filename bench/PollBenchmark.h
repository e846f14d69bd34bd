#pragma once

#include "bench/Benchmark.h"

namespace opentop {

// Transactions per second through OpenTOP's whole stack (ModbusClient's worker thread, the
// RTU backend, DeviceSession::readMany and the codec), reading what a DBU200's backup reads
// (its settings, in the blocks the profile allows, up to 17 registers each), again and again:
// - on a pty without wire timing, against a plain libmodbus loop doing the same reads: the
//   stack's own cost as a ratio (both without the inter-frame gap, which only a line needs);
// - with wire timing at 19200 and 115200 bit/s on a half-duplex simulated line, against what
//   the wire allows for these frames: request, 3.5 characters, the drive's turnaround, reply,
//   3.5 characters.
class PollBenchmark : public Benchmark
{
public:
    QString name() const override { return QStringLiteral("poll"); }
    QString description() const override;
    bool run(const BenchEnvironment& env, BenchReport& report, QString* error) override;

private:
    bool stackOverhead(const BenchEnvironment& env, BenchReport& report, QString* error);
    bool wireFraction(const BenchEnvironment& env, int baud, BenchReport& report, QString* error);
};

} // namespace opentop
