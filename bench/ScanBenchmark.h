#pragma once

#include "bench/Benchmark.h"

#include <QVector>

namespace opentop {

class ModbusClient;
struct DeviceInfo;

// A scan of machine numbers 1-247 with OpenTOP's BusScanner on a half-duplex simulated line
// with wire timing, at 19200 and 115200 bit/s, with the drives' turnaround at 2 ms and at the
// DBU manual's T3 "initial value 10 ms". One drive answers as late as the manual allows
// (T3 10 ms + C1 4 ms): it must still be found, by the late-answer rescue. Peers in the same
// run: a plain libmodbus loop with the same wait, and mbpoll with its default timeout.
class ScanBenchmark : public Benchmark
{
public:
    QString name() const override { return QStringLiteral("scan"); }
    QString description() const override;
    bool run(const BenchEnvironment& env, BenchReport& report, QString* error) override;

    struct Scan
    {
        QVector<int> present;
        double seconds = 0;
        int requests = 0;
        int rescued = 0;
        int waitMs = 0;
        QString error;
    };
    // BusScanner over `client` from `from` to `to`.
    static Scan scan(ModbusClient* client, int from, int to);

private:
    bool runCase(int baud, double turnaroundMs, bool peers, BenchReport& report, QString* error);
};

} // namespace opentop
