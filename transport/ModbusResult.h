#pragma once

#include <QByteArray>
#include <QString>
#include <QVector>

namespace opentop {

enum class ModbusError
{
    Ok,
    Timeout,        // no reply within the response timeout
    CrcError,       // a reply arrived with a bad CRC
    WrongSlave,     // a reply from another machine number (a likely duplicate address)
    Exception,      // the device answered with an exception code
    MalformedReply, // reply with the right CRC but wrong length, function or echo
    PortError,      // the port failed or vanished
    NotConnected,   // no open connection
    InvalidRequest, // rejected before anything was sent
    Cancelled,      // cancelled by the caller before it was sent
};

QString modbusErrorName(ModbusError error);
// Standard exception code names (01 Illegal function ...), plus the DC controller's 0x40/0xFF.
QString modbusExceptionName(quint8 code);

struct ModbusResult
{
    ModbusError error = ModbusError::NotConnected;
    quint8 exceptionCode = 0;   // with ModbusError::Exception
    QVector<quint16> registers; // read replies; echo of the written value(s) for writes
    QByteArray reply;           // the whole reply ADU as received (for raw requests and logs)
    QByteArray rawData;         // raw requests: bytes after the function code, CRC stripped
    QString message;            // human detail, e.g. the OS error for PortError
    int attempts = 0;
    double elapsedMs = 0; // of the last attempt
    // A whole reply from this machine number came after its request had timed out and was
    // discarded before this request was sent (-1: none). A scan asks that drive again.
    int lateReplyFrom = -1;
    // Bytes that were no whole frame (a reply garbled on the line: on a half-duplex line, a
    // request sent into a reply destroys both) were discarded before this request was sent or
    // while the line was drained after it. A scan asks the addresses it asked just before again.
    bool discardedGarbled = false;

    bool ok() const { return error == ModbusError::Ok; }
    // One line for users: "timeout after 3 attempts", "exception 02 Illegal data address".
    QString errorText() const;
};

} // namespace opentop
