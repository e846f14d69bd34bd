#include "model/bus/ScanReasks.h"

#include <algorithm>

namespace opentop {

void ScanReasks::clear(double windowMs)
{
    m_windowMs = windowMs;
    m_suspects.clear();
    m_queue.clear();
    m_answered.clear();
    m_lateAsks.clear();
    m_retries.clear();
}

void ScanReasks::passed(int slave, bool silent, double atMs)
{
    if (silent)
        m_suspects.append({slave, atMs});
    const double keepFromMs = atMs - 2 * m_windowMs;
    while (!m_suspects.isEmpty() && m_suspects.first().atMs < keepFromMs)
        m_suspects.removeFirst();
}

QVector<int> ScanReasks::suspects(double atMs) const
{
    // Counted back from when the current address was asked: its own wait may be long.
    const double fromMs = atMs - m_windowMs;
    QVector<int> slaves;
    for (const Asked& a : m_suspects)
        if (a.atMs >= fromMs)
            slaves << a.slave;
    return slaves;
}

void ScanReasks::askLate(int slave)
{
    if (m_queue.contains(slave) || m_lateAsks.value(slave) >= m_limit)
        return;
    // Asked again with a long wait, its silence is sure: no longer suspect.
    m_suspects.erase(std::remove_if(m_suspects.begin(), m_suspects.end(),
                                    [slave](const Asked& a) { return a.slave == slave; }),
                     m_suspects.end());
    ++m_lateAsks[slave];
    m_queue << slave;
}

int ScanReasks::retryIdentification(int slave)
{
    const int attempt = m_retries.value(slave) + 1;
    if (attempt > m_limit)
        return 0;
    // Asked again next, with the long wait; until then it is not reported.
    m_retries[slave] = attempt;
    m_queue.removeAll(slave);
    m_queue.prepend(slave);
    return attempt;
}

} // namespace opentop
