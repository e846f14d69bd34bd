#pragma once

#include <QDateTime>
#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QTimer>

namespace opentop {

class ModbusClient;

// Opens a lost connection again by itself. When the client's port fails under it
// (ModbusClient::connectionLost: a USB adapter pulled out, a simulator's pty gone, a gateway
// reset) it says so once (lost) and tries to open the same client again, first after 0.5 s,
// then waiting twice as long each time up to 5 s, until the port is back (back: a replugged
// adapter, a simulator restarted on the same link) or, with a limit set, the loss has lasted
// that long (gaveUp). Nothing is sent over the lost port meanwhile; what was asked of it is for
// the caller to stop and start again (opentop-cli monitor). In the model, next to BusMemory, so
// that the window, which reconnects on request (ui/main/Reconnection), can use it as well.
class LinkRecovery : public QObject
{
    Q_OBJECT
public:
    explicit LinkRecovery(ModbusClient* client, QObject* parent = nullptr);

    // The wait before the first attempt and the longest wait between attempts.
    void setDelays(int firstMs, int maxMs);
    // Gives up once the link has been lost this long; 0 (default): never.
    void setGiveUpMs(qint64 ms) { m_giveUpMs = ms; }

    bool isLost() const { return m_lost; }
    QDateTime lostAt() const { return m_lostAt; }
    qint64 lostForMs() const { return m_lost ? m_since.elapsed() : 0; }
    // Why the link was lost, then why the latest attempt failed.
    QString lastError() const { return m_lastError; }
    int attempts() const { return m_attempts; }

    // The link is lost though connectionLost was not heard (it came before this watched):
    // a request found the client closed. Does nothing while already lost.
    void markLost(const QString& why);
    // No more attempts (the caller is ending).
    void stop();

signals:
    void lost(const QDateTime& at, const QString& why);
    void back(qint64 lostMs);
    void gaveUp(qint64 lostMs, const QString& lastError);

private:
    void attempt();
    void opened(bool ok, const QString& error);
    void giveUp();

    QPointer<ModbusClient> m_client;
    QTimer m_retry;
    QTimer m_giveUp;
    QElapsedTimer m_since;
    QDateTime m_lostAt;
    QString m_lastError;
    int m_firstMs = 500;
    int m_maxMs = 5000;
    int m_nextMs = 500;
    qint64 m_giveUpMs = 0;
    int m_attempts = 0;
    bool m_lost = false;
    bool m_opening = false; // an open of ours is under way: its opened() is the answer
    bool m_stopped = false;
};

} // namespace opentop
