#include "transport/MockBackend.h"

#include "transport/RtuFrame.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <algorithm>

namespace opentop {

MockBackend::MockBackend(Handler handler)
    : m_handler(std::move(handler))
{
}

MockBackend::~MockBackend() = default;

bool MockBackend::open(QString* error)
{
    std::lock_guard<std::mutex> lock(m_mutex);
    if (!m_openError.isEmpty()) {
        if (error)
            *error = m_openError;
        return false;
    }
    m_open = true;
    return true;
}

void MockBackend::close()
{
    std::lock_guard<std::mutex> lock(m_mutex);
    m_open = false;
}

bool MockBackend::isOpen() const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_open;
}

QString MockBackend::describe() const
{
    return QStringLiteral("mock");
}

ModbusResult MockBackend::transact(const ModbusRequest& request, int timeoutMs)
{
    ModbusResult result;
    QString failure;
    int noReplyDelayMs = 0;
    int turnaroundMs = 0;
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        if (!m_open) {
            result.error = ModbusError::NotConnected;
            result.message = QCoreApplication::translate("opentop::Transport", "mock is not open");
            return result;
        }
        failure = m_portFailure;
        if (!failure.isEmpty()) {
            m_portFailure.clear();
            m_open = false;
        }
        noReplyDelayMs = m_noReplyDelayMs;
        turnaroundMs = m_turnaroundMs;
    }
    if (!failure.isEmpty()) {
        result.error = ModbusError::PortError;
        result.message = failure;
        logEvent(request, QString(), result.errorText());
        return result;
    }

    const QByteArray adu = RtuFrame::encodeRequest(request);
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_requests.append(adu);
        m_lines.append(request.line);
    }
    logFrame(true, adu, request, request.describe(), QString());
    QElapsedTimer timer;
    timer.start();
    const QByteArray reply = m_handler ? m_handler(adu) : QByteArray();

    if (request.isBroadcast()) {
        if (!sleepInterruptible(turnaroundMs)) {
            result.error = ModbusError::Cancelled;
            return result;
        }
        result.error = ModbusError::Ok;
        result.elapsedMs = double(timer.nsecsElapsed()) / 1e6;
        return result;
    }
    if (reply.isEmpty()) {
        if (!sleepInterruptible(std::min(noReplyDelayMs, timeoutMs) - timer.elapsed())) {
            result.error = ModbusError::Cancelled;
            return result;
        }
        result.error = ModbusError::Timeout;
        result.message = QCoreApplication::translate("opentop::Transport", "no reply within %1 ms")
                             .arg(timeoutMs);
        result.elapsedMs = double(timer.nsecsElapsed()) / 1e6;
        logEvent(request, result.message, result.errorText());
        return result;
    }
    RtuFrame::decodeReply(request, reply, &result);
    result.elapsedMs = double(timer.nsecsElapsed()) / 1e6;
    logReply(reply, quint8(reply.at(0)), reply.size() > 1 ? quint8(reply.at(1)) : -1, request,
             result);
    return result;
}

QVector<QByteArray> MockBackend::requests() const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_requests;
}

QVector<LineFormat> MockBackend::lines() const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_lines;
}

int MockBackend::requestCount() const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return int(m_requests.size());
}

void MockBackend::setOpenError(const QString& error)
{
    std::lock_guard<std::mutex> lock(m_mutex);
    m_openError = error;
}

void MockBackend::setNoReplyDelayMs(int ms)
{
    std::lock_guard<std::mutex> lock(m_mutex);
    m_noReplyDelayMs = ms;
}

void MockBackend::setTurnaroundMs(int ms)
{
    std::lock_guard<std::mutex> lock(m_mutex);
    m_turnaroundMs = ms;
}

void MockBackend::failPort(const QString& message)
{
    std::lock_guard<std::mutex> lock(m_mutex);
    m_portFailure = message;
}

} // namespace opentop
