#pragma once

#include "transport/ModbusResult.h"

namespace opentop {

// How many extra attempts a request gets. The connection's retries are the base; once the line
// has shown itself noisy (a request recently needed a retry to succeed) requests that use the
// connection's default get kNoisyExtra more, so that long operations (backup, restore,
// compare) finish on a line that drops or garbles a few replies. A drive that is simply absent
// never succeeds after a retry, so it does not make the line noisy and is not asked more often.
// An explicit per-request count (e.g. the scanner's 0) is never changed. Worker thread only.
class RetryPolicy
{
public:
    static constexpr int kNoisyExtra = 2;
    static constexpr int kMemory = 64; // transactions a recovered request keeps the line noisy
    static constexpr int kMaxRetries = 10;

    // requestRetries < 0: the connection's `connectionRetries` apply.
    int retriesFor(int requestRetries, int connectionRetries) const;
    // After a request's last attempt.
    void record(const ModbusResult& result);
    bool noisy() const { return m_noisyFor > 0; }

private:
    int m_noisyFor = 0;
};

} // namespace opentop
