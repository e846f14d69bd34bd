#pragma once

#include "transport/ModbusRequest.h"
#include "transport/ModbusResult.h"

#include <QByteArray>

namespace opentop {

// Byte-level encoding and decoding of Modbus RTU frames, for both ends of the line: the client
// (requests out, replies in) and the simulator (requests in, replies out). No I/O here.
class RtuFrame
{
public:
    // Client side.
    static QByteArray encodeRequest(const ModbusRequest& request); // slave + PDU + CRC
    // Length of the complete reply to `request`, once enough of `received` is there to tell;
    // 0 while more bytes are needed. Handles exception replies and 0x2B object lists. Goes by
    // the reply's own function code; -1 when that code's length is unknown (frame by silence).
    static int expectedReplyLength(const ModbusRequest& request, const QByteArray& received);
    // Decodes a complete reply ADU into `result` (error, registers, rawData). Checks in this
    // order: length, CRC (CrcError), slave id (WrongSlave), exception (Exception with code),
    // function, byte count, echo of a write (MalformedReply). Writes return the written values.
    static void decodeReply(const ModbusRequest& request, const QByteArray& adu,
                            ModbusResult* result);

    // Server side.
    // Length of the complete request at the start of `buffer`, 0 while more bytes are needed,
    // -1 when the function code is unknown (framing is then done by silence).
    static int expectedRequestLength(const QByteArray& buffer);
    // Parses a CRC-checked request ADU. Returns false for a frame too short for its function.
    static bool decodeRequest(const QByteArray& adu, ModbusRequest* request);
    static QByteArray encodeReadReply(quint8 slave, quint8 function,
                                      const QVector<quint16>& values);
    static QByteArray encodeWriteSingleReply(quint8 slave, quint16 address, quint16 value);
    static QByteArray encodeWriteMultipleReply(quint8 slave, quint16 address, quint16 count);
    static QByteArray encodeException(quint8 slave, quint8 function, quint8 code);
    static QByteArray encodeRaw(quint8 slave, quint8 function, const QByteArray& data);

    static QString toHex(const QByteArray& bytes);  // "01 03 CA 03 00 01 4B D2"
    static QByteArray fromHex(const QString& text); // accepts spaces, "h" suffixes
};

} // namespace opentop
