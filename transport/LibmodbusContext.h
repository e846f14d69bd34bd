#pragma once

#include <QByteArray>
#include <QString>

struct _modbus; // libmodbus' modbus_t, kept out of this header

namespace opentop {

struct ModbusResult;

// The libmodbus context of one connection, owned: set up and connected, closed and freed here,
// and every libmodbus call LibmodbusBackend makes on it. Also what libmodbus' and the system's
// error numbers mean: their text, which of them end the connection, and which of them say what
// was wrong with a reply rather than with the port.
class LibmodbusContext
{
public:
    LibmodbusContext() = default;
    ~LibmodbusContext() { reset(); }
    LibmodbusContext(const LibmodbusContext&) = delete;
    LibmodbusContext& operator=(const LibmodbusContext&) = delete;

    // Takes `ctx` (made by modbus_new_rtu/tcp), sets no error recovery and the timeouts, and
    // connects it: 0, or the errno of a failed connect (the context is freed then).
    int connect(_modbus* ctx, double responseTimeoutMs, int byteTimeoutMs);
    // Closes and frees the context, if there is one.
    void reset();
    _modbus* get() const { return m_ctx; }
    // The connection's descriptor; -1 without a context.
    int socket() const;
#ifdef Q_OS_WIN
    // A COM port's HANDLE, which libmodbus keeps to itself on Windows (socket() is -1 there):
    // found once connected (ComPort::handleOf); null for TCP, or when it cannot be found.
    void* commHandle() const;
#endif

    void setResponseTimeout(double ms);
    void setByteTimeout(int ms);
    void flush();
    // Sends id + PDU as they are (libmodbus adds the CRC or the MBAP header); false (errno) when
    // it failed.
    bool sendRaw(const QByteArray& idAndPdu);
    // Reads the reply to a standard request to `slave` within `timeoutMs` into `buffer`, as
    // modbus_receive_confirmation: its length, 0 for a whole frame from another id, -1 (errno).
    int receive(quint8 slave, double timeoutMs, QByteArray* buffer);

    static QString errorText(int err);
    // Errors after which the connection is gone (unplugged adapter, closed socket).
    static bool isFatal(int err);
    // A failed receive's errno when it tells what was wrong with the reply: fills `result`
    // (Timeout for a reply that stopped, CrcError, MalformedReply) and returns true. False for
    // any other error: the port failed.
    static bool replyFault(int err, ModbusResult* result);

private:
    _modbus* m_ctx = nullptr;
#ifdef Q_OS_WIN
    void* m_comm = nullptr;
#endif
};

} // namespace opentop
