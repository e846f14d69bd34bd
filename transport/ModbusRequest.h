#pragma once

#include "transport/LineFormat.h"

#include <QByteArray>
#include <QString>
#include <QVector>
#include <cstdint>

namespace opentop {

// One Modbus transaction as the rest of the program describes it. The transport turns it into
// an ADU (RTU or TCP); RtuFrame builds the PDU so that tests can check bytes against the manuals.
struct ModbusRequest
{
    enum Function : quint8
    {
        ReadHolding = 0x03,
        ReadInput = 0x04,
        WriteSingle = 0x06,
        WriteMultiple = 0x10,
        EncapsulatedInterface = 0x2B,
    };
    // User commands always go before background polling on the bus.
    enum class Priority
    {
        Poll = 0,
        Normal = 1,
        User = 2
    };

    quint8 slave = 1;
    quint8 function = ReadHolding;
    quint16 address = 0;
    quint16 count = 0;       // registers to read or written by 0x10
    QVector<quint16> values; // 0x06: one value; 0x10: count values
    QByteArray rawData;      // raw requests: bytes after the function code
    bool raw = false;        // function code libmodbus has no API for
    int timeoutMs = -1;      // -1: the connection's default
    int retries = -1;        // -1: the connection's default
    Priority priority = Priority::Normal;
    // The format of the drive it goes to; unset: the client's table for the slave, else the
    // port's (a broadcast with none goes out in every format the table holds).
    LineFormat line;
    // A scan's question to a machine number that has not answered yet. After a request timed
    // out, every other request waits until the longest reply to it could have ended (it may
    // still be on the wire: LibmodbusBackend); a probe after a probe goes at once, because the
    // scan sees a collision as a garbled frame and asks that address again. This keeps an empty
    // address at one short wait.
    bool probe = false;

    static ModbusRequest readHolding(quint8 slave, quint16 address, quint16 count);
    static ModbusRequest readInput(quint8 slave, quint16 address, quint16 count);
    static ModbusRequest writeSingle(quint8 slave, quint16 address, quint16 value);
    static ModbusRequest writeMultiple(quint8 slave, quint16 address,
                                       const QVector<quint16>& values);
    static ModbusRequest rawRequest(quint8 slave, quint8 function, const QByteArray& data);
    // 0x2B / 0x0E read device identification (basic or regular category).
    static ModbusRequest readDeviceIdentification(quint8 slave, quint8 readCode = 1,
                                                  quint8 objectId = 0);

    bool isBroadcast() const { return slave == 0; }
    bool isWrite() const { return function == WriteSingle || function == WriteMultiple; }
    bool isRead() const { return function == ReadHolding || function == ReadInput; }
    // The PDU: function code followed by its data (no slave id, no CRC).
    QByteArray pdu() const;
    // Checks the request is one a Modbus device could accept at all; empty when valid.
    QString validate() const;
    QString describe() const;
};

} // namespace opentop
