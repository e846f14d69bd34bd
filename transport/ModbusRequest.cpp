#include "transport/ModbusRequest.h"

#include <QCoreApplication>
#include <QStringList>

namespace opentop {

namespace {

constexpr int kMaxReadCount = 125;  // Modbus: 125 registers fit in one 0x03/0x04 reply
constexpr int kMaxWriteCount = 123; // Modbus: 123 registers fit in one 0x10 request
constexpr int kMaxRawData = 252;    // RTU ADU 256 = id + function + 252 + CRC
constexpr int kMaxSlave = 247;      // 248-255 are reserved by the standard

void appendWord(QByteArray& bytes, quint16 value)
{
    bytes.append(static_cast<char>(value >> 8));
    bytes.append(static_cast<char>(value & 0xFF));
}

QString hex2(quint8 value)
{
    return QString::number(value, 16).rightJustified(2, QLatin1Char('0')).toUpper();
}

QString hex4(quint16 value)
{
    return QStringLiteral("0x") +
           QString::number(value, 16).rightJustified(4, QLatin1Char('0')).toUpper();
}

QString valueList(const QVector<quint16>& values)
{
    QStringList parts;
    for (int i = 0; i < values.size() && i < 8; ++i)
        parts << QString::number(values[i]);
    if (values.size() > 8)
        parts << QStringLiteral("…");
    return parts.join(QStringLiteral(", "));
}

bool isStandard(quint8 function)
{
    return function == ModbusRequest::ReadHolding || function == ModbusRequest::ReadInput ||
           function == ModbusRequest::WriteSingle || function == ModbusRequest::WriteMultiple;
}

} // namespace

ModbusRequest ModbusRequest::readHolding(quint8 slave, quint16 address, quint16 count)
{
    ModbusRequest r;
    r.slave = slave;
    r.function = ReadHolding;
    r.address = address;
    r.count = count;
    return r;
}

ModbusRequest ModbusRequest::readInput(quint8 slave, quint16 address, quint16 count)
{
    ModbusRequest r = readHolding(slave, address, count);
    r.function = ReadInput;
    return r;
}

ModbusRequest ModbusRequest::writeSingle(quint8 slave, quint16 address, quint16 value)
{
    ModbusRequest r;
    r.slave = slave;
    r.function = WriteSingle;
    r.address = address;
    r.count = 1;
    r.values = {value};
    return r;
}

ModbusRequest ModbusRequest::writeMultiple(quint8 slave, quint16 address,
                                           const QVector<quint16>& values)
{
    ModbusRequest r;
    r.slave = slave;
    r.function = WriteMultiple;
    r.address = address;
    r.count = static_cast<quint16>(values.size());
    r.values = values;
    return r;
}

ModbusRequest ModbusRequest::rawRequest(quint8 slave, quint8 function, const QByteArray& data)
{
    ModbusRequest r;
    r.slave = slave;
    r.function = function;
    r.rawData = data;
    r.raw = true;
    return r;
}

ModbusRequest ModbusRequest::readDeviceIdentification(quint8 slave, quint8 readCode,
                                                      quint8 objectId)
{
    QByteArray data;
    data.append(static_cast<char>(0x0E)); // MEI type: read device identification
    data.append(static_cast<char>(readCode));
    data.append(static_cast<char>(objectId));
    return rawRequest(slave, EncapsulatedInterface, data);
}

QByteArray ModbusRequest::pdu() const
{
    QByteArray bytes;
    bytes.append(static_cast<char>(function));
    if (raw || !isStandard(function)) {
        bytes.append(rawData);
        return bytes;
    }
    appendWord(bytes, address);
    switch (function) {
    case ReadHolding:
    case ReadInput:
        appendWord(bytes, count);
        break;
    case WriteSingle:
        appendWord(bytes, values.isEmpty() ? 0 : values.first());
        break;
    case WriteMultiple:
        appendWord(bytes, count);
        bytes.append(static_cast<char>((count * 2) & 0xFF));
        for (int i = 0; i < count; ++i)
            appendWord(bytes, i < values.size() ? values[i] : 0);
        break;
    default:
        break;
    }
    return bytes;
}

QString ModbusRequest::validate() const
{
    if (slave > kMaxSlave)
        return QCoreApplication::translate(
                   "opentop::Transport",
                   "Slave address %1 is not allowed: use 1–247, or 0 to broadcast a write.")
            .arg(slave);
    if (function == 0 || function >= 0x80)
        return QCoreApplication::translate("opentop::Transport",
                                           "Function code 0x%1 is not allowed: use 0x01–0x7F.")
            .arg(hex2(function));
    if (timeoutMs != -1 && (timeoutMs < 10 || timeoutMs > 10000))
        return QCoreApplication::translate(
                   "opentop::Transport",
                   "Timeout %1 ms is not allowed: use 10–10000 ms, or -1 for the default.")
            .arg(timeoutMs);
    if (retries != -1 && (retries < 0 || retries > 10))
        return QCoreApplication::translate(
                   "opentop::Transport",
                   "%1 retries are not allowed: use 0–10, or -1 for the default.")
            .arg(retries);

    if (line.isSet()) {
        const QString invalid = line.validate();
        if (!invalid.isEmpty())
            return invalid;
    }
    // A broadcast gets no reply, so only a write means anything; the T-net drives execute only
    // functions 06h and 10h sent to machine number 0 (DBU manual 11-3, function code table).
    if (isBroadcast() && function != WriteSingle && function != WriteMultiple)
        return QCoreApplication::translate(
                   "opentop::Transport",
                   "Function 0x%1 cannot be broadcast: only functions 06h and 10h (writes) may be "
                   "sent to machine number 0; use slave address 1–247.")
            .arg(hex2(function));
    if (raw || !isStandard(function)) {
        if (!raw)
            return QCoreApplication::translate("opentop::Transport",
                                               "Function code 0x%1 must be sent as a raw request.")
                .arg(hex2(function));
        if (rawData.size() > kMaxRawData)
            return QCoreApplication::translate(
                       "opentop::Transport",
                       "Raw request data of %1 bytes is too long: at most %2 bytes.")
                .arg(rawData.size())
                .arg(kMaxRawData);
        return QString();
    }

    const quint32 last = quint32(address) + quint32(count) - 1;
    switch (function) {
    case ReadHolding:
    case ReadInput:
        if (count < 1 || count > kMaxReadCount)
            return QCoreApplication::translate(
                       "opentop::Transport",
                       "Cannot read %1 registers at once: use 1–125 registers.")
                .arg(count);
        break;
    case WriteSingle:
        if (values.size() != 1)
            return QCoreApplication::translate(
                       "opentop::Transport", "Write single register needs exactly 1 value, not %1.")
                .arg(values.size());
        return QString();
    case WriteMultiple:
        if (count < 1 || count > kMaxWriteCount)
            return QCoreApplication::translate(
                       "opentop::Transport",
                       "Cannot write %1 registers at once: use 1–123 registers.")
                .arg(count);
        if (values.size() != count)
            return QCoreApplication::translate("opentop::Transport",
                                               "%1 values given for %2 registers.")
                .arg(values.size())
                .arg(count);
        break;
    default:
        break;
    }
    if (last > 0xFFFF)
        return QCoreApplication::translate("opentop::Transport",
                                           "Registers %1 ×%2 run past the last address 0xFFFF.")
            .arg(hex4(address))
            .arg(count);
    return QString();
}

QString ModbusRequest::describe() const
{
    QString text;
    if (function == EncapsulatedInterface && rawData.size() >= 3 && quint8(rawData[0]) == 0x0E) {
        text = QCoreApplication::translate("opentop::Transport",
                                           "device identification code %1 object %2")
                   .arg(quint8(rawData[1]))
                   .arg(hex2(quint8(rawData[2])));
    } else if (raw || !isStandard(function)) {
        QStringList bytes;
        for (char c : rawData)
            bytes << hex2(quint8(c));
        text = QCoreApplication::translate("opentop::Transport", "raw %1 %2")
                   .arg(hex2(function), bytes.join(QLatin1Char(' ')))
                   .trimmed();
    } else if (isRead()) {
        text = QCoreApplication::translate("opentop::Transport", "read %1 %2 ×%3")
                   .arg(hex2(function), hex4(address))
                   .arg(count);
    } else if (function == WriteSingle) {
        text = QCoreApplication::translate("opentop::Transport", "write %1 %2 = %3")
                   .arg(hex2(function), hex4(address), valueList(values));
    } else {
        text = QCoreApplication::translate("opentop::Transport", "write %1 %2 ×%3 = %4")
                   .arg(hex2(function), hex4(address))
                   .arg(count)
                   .arg(valueList(values));
    }
    if (isBroadcast())
        text = QCoreApplication::translate("opentop::Transport", "broadcast %1").arg(text);
    return text;
}

} // namespace opentop
