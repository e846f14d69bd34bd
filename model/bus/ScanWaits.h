#pragma once

#include "transport/LineFormat.h"

namespace opentop {

class ModbusClient;
struct ConnectionSettings;

// How long a scan waits for each reply, and the line format it asks in (the waits follow it):
// an empty address costs one short wait for the first byte; one that has answered gets a whole
// reply's wait; one asked again, and the last of the pass, get four waits or more so that a
// late reply is still caught (docs/communication.md, "Scans").
class ScanWaits
{
public:
    // ModbusRequest refuses timeouts below 10 ms; shorter waits are raised to it.
    static constexpr int kMinWaitMs = 10;
    static constexpr int kMaxWaitMs = 5000;
    // A present device's time to answer after the request and the 3.5 character gap: the DBU
    // manual's T3 "initial value 10 ms" (11-1); a slower one is found by the late-answer rescue.
    static constexpr double kAnswerBudgetMs = 10.0;

    // Per-address wait for the first byte of a reply, from sending: the request's transmission
    // + the 3.5 character gap + the answer budget + a small margin + what the adapter adds
    // (a USB adapter without low latency holds received bytes up to its latency timer). Only
    // the first byte has to come within it; the rest of a reply is read by the byte timeout.
    static int defaultWaitMs(const ConnectionSettings& settings, int adapterLatencyMs = 0);
    // The wait for a whole reply of `replyBytes` when its first byte may come as late as
    // `firstByteWaitMs` (also where the adapter passes it on only whole).
    static int wholeReplyWaitMs(const ConnectionSettings& settings, int firstByteWaitMs,
                                int replyBytes);

    explicit ScanWaits(ModbusClient* client)
        : m_client(client)
    {
    }

    // The wait for the next scan; 0 uses defaultWaitMs().
    void setWaitMs(int ms);
    // The format every request of the next scan goes out in (a pass for drives of another
    // format); unset: each drive's own (ModbusClient::driveLine), else the port's.
    void setLine(const LineFormat& format) { m_line = format; }
    LineFormat line() const { return m_line; }
    // The wait for `slave` (0: the port's): the given one, else derived from the format it is
    // asked in.
    int waitFor(int slave) const;
    // At a scan's start: the wait of its pass, kept until it ends.
    void begin() { m_passWaitMs = waitFor(0); }
    int passWaitMs() const { return m_passWaitMs; }

    enum class Asking
    {
        First,      // an address not heard from yet
        Present,    // it has answered (another family's read, a garbled frame)
        LastOfPass, // no next request catches its late reply
        Again       // asked again: it answered late, or its identification failed
    };
    // The timeout of a request to `slave` reading `registers`.
    int timeoutMs(int slave, int registers, Asking asking) const;

private:
    // The connection's settings in the format `slave` is asked in.
    ConnectionSettings settingsFor(int slave) const;

    ModbusClient* m_client;
    int m_waitMs = 0;
    LineFormat m_line;
    int m_passWaitMs = 0;
};

} // namespace opentop
