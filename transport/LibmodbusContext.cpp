#include "transport/LibmodbusContext.h"

#include "transport/ModbusResult.h"

#include <QCoreApplication>
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <modbus.h>
#ifdef Q_OS_WIN
#include "transport/ComPort_win.h"
#include "transport/WinError_win.h"
#endif

namespace opentop {

namespace {

constexpr int kBufferSize = MODBUS_TCP_MAX_ADU_LENGTH; // large enough for RTU too

} // namespace

int LibmodbusContext::connect(_modbus* ctx, double responseTimeoutMs, int byteTimeoutMs)
{
    reset();
    m_ctx = ctx;
    modbus_set_error_recovery(m_ctx, MODBUS_ERROR_RECOVERY_NONE);
    setResponseTimeout(responseTimeoutMs);
    setByteTimeout(byteTimeoutMs);
    if (modbus_connect(m_ctx) == -1) {
        int err = errno;
#ifdef Q_OS_WIN
        // libmodbus' Win32 serial open leaves errno alone (the system's last error says why);
        // its TCP connect may leave a Winsock code in it.
        err = WinError::connectErrno(err);
#endif
        modbus_free(m_ctx);
        m_ctx = nullptr;
        return err;
    }
#ifdef Q_OS_WIN
    if (modbus_get_socket(m_ctx) < 0) // a COM port: no socket
        m_comm = ComPort::handleOf(m_ctx);
#endif
    modbus_flush(m_ctx);
    return 0;
}

void LibmodbusContext::reset()
{
    if (!m_ctx)
        return;
    modbus_close(m_ctx);
    modbus_free(m_ctx);
    m_ctx = nullptr;
#ifdef Q_OS_WIN
    m_comm = nullptr;
#endif
}

int LibmodbusContext::socket() const
{
    return m_ctx ? modbus_get_socket(m_ctx) : -1;
}

#ifdef Q_OS_WIN
void* LibmodbusContext::commHandle() const
{
    return m_comm;
}
#endif

void LibmodbusContext::setResponseTimeout(double ms)
{
    // libmodbus rejects 0 s 0 µs.
    const auto us = static_cast<uint32_t>(std::max(1000.0, std::ceil(ms * 1000)));
    modbus_set_response_timeout(m_ctx, us / 1000000, us % 1000000);
}

void LibmodbusContext::setByteTimeout(int ms)
{
    modbus_set_byte_timeout(m_ctx, uint32_t(ms / 1000), uint32_t((ms % 1000) * 1000));
}

void LibmodbusContext::flush()
{
    modbus_flush(m_ctx);
}

bool LibmodbusContext::sendRaw(const QByteArray& idAndPdu)
{
    return modbus_send_raw_request(m_ctx, reinterpret_cast<const uint8_t*>(idAndPdu.constData()),
                                   int(idAndPdu.size())) != -1;
}

int LibmodbusContext::receive(quint8 slave, double timeoutMs, QByteArray* buffer)
{
    *buffer = QByteArray(kBufferSize, '\0');
    modbus_set_slave(m_ctx, slave);
    setResponseTimeout(timeoutMs);
    errno = 0;
    return modbus_receive_confirmation(m_ctx, reinterpret_cast<uint8_t*>(buffer->data()));
}

QString LibmodbusContext::errorText(int err)
{
#ifdef Q_OS_WIN
    if (const char* text = WinError::posixText(err)) // codes the Windows C library cannot name
        return QString::fromLatin1(text);
#endif
    return QString::fromLocal8Bit(modbus_strerror(err));
}

bool LibmodbusContext::isFatal(int err)
{
    switch (err) {
    case EIO:
    case ENXIO:
    case EBADF:
    case ENODEV:
    case ECONNRESET:
    case ECONNABORTED:
    case EPIPE:
    case ENOTCONN:
#ifdef ESHUTDOWN // not in MinGW's errno.h
    case ESHUTDOWN:
#endif
        return true;
    default:
        return false;
    }
}

bool LibmodbusContext::replyFault(int err, ModbusResult* result)
{
    switch (err) {
    case ETIMEDOUT:
        // The reply started but stopped: a master discards such a frame.
        result->error = ModbusError::Timeout;
        result->message = QCoreApplication::translate("opentop::Transport", "reply incomplete");
        return true;
    case EMBBADCRC:
        result->error = ModbusError::CrcError;
        result->message = QCoreApplication::translate("opentop::Transport", "CRC mismatch");
        return true;
    case EMBBADDATA:
        result->error = ModbusError::MalformedReply;
        result->message = errorText(err);
        return true;
    default:
        return false;
    }
}

} // namespace opentop
