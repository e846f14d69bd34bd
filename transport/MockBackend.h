#pragma once

#include "transport/ModbusBackend.h"

#include <QVector>
#include <functional>
#include <mutex>

namespace opentop {

// A backend for unit tests: a handler plays the devices. It gets each request as an RTU ADU and
// returns the reply ADU, or nothing for "no reply" (a Timeout, after noReplyDelayMs at most).
// Every request is recorded; frames are logged like on a real line.
class MockBackend : public ModbusBackend
{
public:
    using Handler = std::function<QByteArray(const QByteArray& requestAdu)>;

    explicit MockBackend(Handler handler);
    ~MockBackend() override;

    bool open(QString* error) override;
    void close() override;
    bool isOpen() const override;
    ModbusResult transact(const ModbusRequest& request, int timeoutMs) override;
    QString describe() const override;

    // Thread-safe: tests read these while the worker runs.
    QVector<QByteArray> requests() const;
    int requestCount() const;
    // The format each request carried (ModbusRequest::line), in order.
    QVector<LineFormat> lines() const;
    void setOpenError(const QString& error);
    // How long "no reply" takes, capped by the request's timeout; 0 (default) returns at once.
    void setNoReplyDelayMs(int ms);
    void setTurnaroundMs(int ms);
    // The next transact fails with PortError and closes the backend (an unplugged adapter).
    void failPort(const QString& message);

private:
    Handler m_handler;
    mutable std::mutex m_mutex;
    QVector<QByteArray> m_requests;
    QVector<LineFormat> m_lines;
    QString m_openError;
    QString m_portFailure;
    int m_noReplyDelayMs = 0;
    int m_turnaroundMs = 0;
    bool m_open = false;
};

} // namespace opentop
