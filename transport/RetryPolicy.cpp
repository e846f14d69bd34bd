#include "transport/RetryPolicy.h"

#include <algorithm>

namespace opentop {

int RetryPolicy::retriesFor(int requestRetries, int connectionRetries) const
{
    if (requestRetries >= 0)
        return requestRetries;
    if (connectionRetries <= 0 || !noisy())
        return std::max(0, connectionRetries);
    return std::min(kMaxRetries, connectionRetries + kNoisyExtra);
}

void RetryPolicy::record(const ModbusResult& result)
{
    if (result.ok() && result.attempts > 1)
        m_noisyFor = kMemory;
    else if (m_noisyFor > 0)
        --m_noisyFor;
}

} // namespace opentop
