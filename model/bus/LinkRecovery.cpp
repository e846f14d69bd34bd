#include "model/bus/LinkRecovery.h"

#include "transport/ModbusClient.h"

#include <algorithm>
#include <limits>

namespace opentop {

LinkRecovery::LinkRecovery(ModbusClient* client, QObject* parent)
    : QObject(parent)
    , m_client(client)
{
    m_retry.setSingleShot(true);
    m_giveUp.setSingleShot(true);
    connect(&m_retry, &QTimer::timeout, this, &LinkRecovery::attempt);
    connect(&m_giveUp, &QTimer::timeout, this, &LinkRecovery::giveUp);
    connect(client, &ModbusClient::connectionLost, this, &LinkRecovery::markLost);
    connect(client, &ModbusClient::opened, this, &LinkRecovery::opened);
}

void LinkRecovery::setDelays(int firstMs, int maxMs)
{
    m_firstMs = std::max(1, firstMs);
    m_maxMs = std::max(m_firstMs, maxMs);
    m_nextMs = m_firstMs;
}

void LinkRecovery::markLost(const QString& why)
{
    if (m_lost || m_stopped)
        return;
    m_lost = true;
    m_lostAt = QDateTime::currentDateTime();
    m_since.start();
    m_lastError = why;
    m_attempts = 0;
    m_nextMs = m_firstMs;
    m_retry.start(m_nextMs);
    // Measured from the loss, not from an attempt: an attempt on a gateway may take seconds.
    if (m_giveUpMs > 0)
        m_giveUp.start(int(std::min<qint64>(m_giveUpMs, std::numeric_limits<int>::max())));
    emit lost(m_lostAt, why);
}

void LinkRecovery::stop()
{
    m_stopped = true;
    m_retry.stop();
    m_giveUp.stop();
}

void LinkRecovery::attempt()
{
    if (!m_lost || m_stopped || !m_client)
        return;
    ++m_attempts;
    m_opening = true;
    m_client->open(); // on the client's worker: this thread goes on; opened() answers
}

void LinkRecovery::opened(bool ok, const QString& error)
{
    // The client says so for every open, also the first one, made before the link was lost.
    if (!m_opening)
        return;
    m_opening = false;
    if (!m_lost || m_stopped)
        return;
    if (ok) {
        const qint64 lostMs = m_since.elapsed();
        m_lost = false;
        m_retry.stop();
        m_giveUp.stop();
        m_lastError.clear();
        emit back(lostMs);
        return;
    }
    m_lastError = error;
    m_nextMs = std::min(m_nextMs * 2, m_maxMs);
    m_retry.start(m_nextMs);
}

void LinkRecovery::giveUp()
{
    if (!m_lost || m_stopped)
        return;
    const qint64 lostMs = m_since.elapsed();
    // A coarse timer may fire up to 5 % early: "gave up after 300 s" must mean it lasted that.
    if (lostMs < m_giveUpMs) {
        m_giveUp.start(int(std::min<qint64>(m_giveUpMs - lostMs, std::numeric_limits<int>::max())));
        return;
    }
    stop();
    emit gaveUp(lostMs, m_lastError);
}

} // namespace opentop
