#include "transport/RtuFrame.h"

#include "transport/ModbusCrc.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <QStringList>

namespace opentop {

namespace {

constexpr int kMaxAdu = 256;

quint8 byteAt(const QByteArray& bytes, int index)
{
    return static_cast<quint8>(bytes.at(index));
}

quint16 wordAt(const QByteArray& bytes, int index)
{
    return static_cast<quint16>((byteAt(bytes, index) << 8) | byteAt(bytes, index + 1));
}

void appendWord(QByteArray& bytes, quint16 value)
{
    bytes.append(static_cast<char>(value >> 8));
    bytes.append(static_cast<char>(value & 0xFF));
}

QString hex2(quint8 value)
{
    return QString::number(value, 16).rightJustified(2, QLatin1Char('0')).toUpper();
}

QByteArray header(quint8 slave, quint8 function)
{
    QByteArray bytes;
    bytes.append(static_cast<char>(slave));
    bytes.append(static_cast<char>(function));
    return bytes;
}

// Length of a 0x2B/0x0E reply from its object list; 0 while incomplete.
int deviceIdentificationLength(const QByteArray& received)
{
    // id, 2B, 0E, read code, conformity, more follows, next object id, object count
    if (received.size() < 8)
        return 0;
    const int objects = byteAt(received, 7);
    int pos = 8;
    for (int i = 0; i < objects; ++i) {
        if (received.size() < pos + 2)
            return 0;
        pos += 2 + byteAt(received, pos + 1);
        if (pos + 2 > kMaxAdu)
            return pos + 2; // too long for RTU; the caller reports it
    }
    return pos + 2;
}

void malformed(ModbusResult* result, const QString& why)
{
    result->error = ModbusError::MalformedReply;
    result->message = why;
}

} // namespace

QByteArray RtuFrame::encodeRequest(const ModbusRequest& request)
{
    QByteArray adu;
    adu.append(static_cast<char>(request.slave));
    adu.append(request.pdu());
    return ModbusCrc::append(adu);
}

int RtuFrame::expectedReplyLength(const ModbusRequest& request, const QByteArray& received)
{
    Q_UNUSED(request); // the reply's own function code decides, as a receiver must
    if (received.size() < 2)
        return 0;
    const quint8 function = byteAt(received, 1);
    if (function & 0x80)
        return 5; // id, function | 0x80, exception code, CRC
    switch (function) {
    case 0x01:
    case 0x02:
    case 0x03:
    case 0x04:
    case 0x0C:
    case 0x11:
    case 0x17:
        return received.size() < 3 ? 0 : 5 + byteAt(received, 2);
    case 0x05:
    case 0x06:
    case 0x08:
    case 0x0B:
    case 0x0F:
    case 0x10:
        return 8;
    case 0x07:
        return 5;
    case 0x16:
        return 10;
    case ModbusRequest::EncapsulatedInterface:
        if (received.size() < 3)
            return 0;
        if (byteAt(received, 2) != 0x0E)
            return -1;
        return deviceIdentificationLength(received);
    default:
        return -1; // unknown: frame by silence
    }
}

void RtuFrame::decodeReply(const ModbusRequest& request, const QByteArray& adu,
                           ModbusResult* result)
{
    result->reply = adu;
    result->registers.clear();
    result->rawData.clear();
    result->exceptionCode = 0;
    result->message.clear();
    if (adu.size() < 4) {
        malformed(result,
                  QCoreApplication::translate("opentop::Transport", "reply too short (%1 bytes)")
                      .arg(adu.size()));
        return;
    }
    if (!ModbusCrc::check(adu)) {
        result->error = ModbusError::CrcError;
        result->message = QCoreApplication::translate("opentop::Transport", "CRC mismatch");
        return;
    }
    const quint8 slave = byteAt(adu, 0);
    if (slave != request.slave) {
        result->error = ModbusError::WrongSlave;
        result->message =
            QCoreApplication::translate("opentop::Transport", "reply from slave %1, expected %2")
                .arg(slave)
                .arg(request.slave);
        return;
    }
    const quint8 function = byteAt(adu, 1);
    if (function == (request.function | 0x80)) {
        if (adu.size() != 5) {
            malformed(result, QCoreApplication::translate("opentop::Transport",
                                                          "exception reply of %1 bytes")
                                  .arg(adu.size()));
            return;
        }
        result->error = ModbusError::Exception;
        result->exceptionCode = byteAt(adu, 2);
        result->message = modbusExceptionName(result->exceptionCode);
        return;
    }
    if (function != request.function) {
        malformed(result, QCoreApplication::translate("opentop::Transport",
                                                      "reply function %1, expected %2")
                              .arg(hex2(function), hex2(request.function)));
        return;
    }
    const int expected = expectedReplyLength(request, adu);
    if (expected == 0) {
        malformed(result, QCoreApplication::translate("opentop::Transport",
                                                      "reply ends inside its own data"));
        return;
    }
    if (expected > 0 && adu.size() != expected) {
        malformed(result, QCoreApplication::translate("opentop::Transport",
                                                      "reply of %1 bytes, expected %2")
                              .arg(adu.size())
                              .arg(expected));
        return;
    }
    if (request.raw) {
        if (function == ModbusRequest::EncapsulatedInterface && !request.rawData.isEmpty() &&
            byteAt(adu, 2) != byteAt(request.rawData, 0)) {
            malformed(result,
                      QCoreApplication::translate("opentop::Transport", "MEI type %1, expected %2")
                          .arg(hex2(byteAt(adu, 2)), hex2(byteAt(request.rawData, 0))));
            return;
        }
        result->rawData = adu.mid(2, adu.size() - 4);
        result->error = ModbusError::Ok;
        return;
    }
    switch (function) {
    case ModbusRequest::ReadHolding:
    case ModbusRequest::ReadInput: {
        const int byteCount = byteAt(adu, 2);
        if (byteCount != request.count * 2) {
            malformed(result, QCoreApplication::translate("opentop::Transport",
                                                          "byte count %1, expected %2")
                                  .arg(byteCount)
                                  .arg(request.count * 2));
            return;
        }
        for (int i = 0; i < request.count; ++i)
            result->registers.append(wordAt(adu, 3 + 2 * i));
        break;
    }
    case ModbusRequest::WriteSingle: {
        const quint16 value = request.values.value(0);
        if (wordAt(adu, 2) != request.address || wordAt(adu, 4) != value) {
            malformed(result, QCoreApplication::translate("opentop::Transport",
                                                          "echo %1 = %2 differs from the write")
                                  .arg(wordAt(adu, 2))
                                  .arg(wordAt(adu, 4)));
            return;
        }
        result->registers = {value};
        break;
    }
    case ModbusRequest::WriteMultiple:
        if (wordAt(adu, 2) != request.address || wordAt(adu, 4) != request.count) {
            malformed(result, QCoreApplication::translate("opentop::Transport",
                                                          "echo %1 ×%2 differs from the write")
                                  .arg(wordAt(adu, 2))
                                  .arg(wordAt(adu, 4)));
            return;
        }
        result->registers = request.values;
        break;
    default:
        result->rawData = adu.mid(2, adu.size() - 4);
        break;
    }
    result->error = ModbusError::Ok;
}

int RtuFrame::expectedRequestLength(const QByteArray& buffer)
{
    if (buffer.size() < 2)
        return 0;
    switch (byteAt(buffer, 1)) {
    case 0x01:
    case 0x02:
    case 0x03:
    case 0x04:
    case 0x05:
    case 0x06:
    case 0x08:
        return 8;
    case 0x07:
    case 0x0B:
    case 0x0C:
    case 0x11:
        return 4;
    case 0x0F:
    case 0x10:
        return buffer.size() < 7 ? 0 : 9 + byteAt(buffer, 6);
    case 0x16:
        return 10;
    case 0x17:
        return buffer.size() < 11 ? 0 : 13 + byteAt(buffer, 10);
    case ModbusRequest::EncapsulatedInterface:
        if (buffer.size() < 3)
            return 0;
        return byteAt(buffer, 2) == 0x0E ? 7 : -1;
    default:
        return -1;
    }
}

bool RtuFrame::decodeRequest(const QByteArray& adu, ModbusRequest* request)
{
    if (adu.size() < 4)
        return false;
    ModbusRequest r;
    r.slave = byteAt(adu, 0);
    r.function = byteAt(adu, 1);
    const int expected = expectedRequestLength(adu);
    // 0: too short to tell its own length (a 0x10 frame cut before its byte count)
    if (expected == 0 || (expected > 0 && adu.size() < expected))
        return false;
    switch (r.function) {
    case ModbusRequest::ReadHolding:
    case ModbusRequest::ReadInput:
        r.address = wordAt(adu, 2);
        r.count = wordAt(adu, 4);
        break;
    case ModbusRequest::WriteSingle:
        r.address = wordAt(adu, 2);
        r.count = 1;
        r.values = {wordAt(adu, 4)};
        break;
    case ModbusRequest::WriteMultiple: {
        r.address = wordAt(adu, 2);
        r.count = wordAt(adu, 4);
        const int byteCount = byteAt(adu, 6);
        if (byteCount != r.count * 2 || adu.size() < 9 + byteCount)
            return false;
        for (int i = 0; i < r.count; ++i)
            r.values.append(wordAt(adu, 7 + 2 * i));
        break;
    }
    default:
        r.raw = true;
        r.rawData = adu.mid(2, (expected > 0 ? expected : adu.size()) - 4);
        break;
    }
    *request = r;
    return true;
}

QByteArray RtuFrame::encodeReadReply(quint8 slave, quint8 function, const QVector<quint16>& values)
{
    QByteArray adu = header(slave, function);
    adu.append(static_cast<char>((values.size() * 2) & 0xFF));
    for (quint16 v : values)
        appendWord(adu, v);
    return ModbusCrc::append(adu);
}

QByteArray RtuFrame::encodeWriteSingleReply(quint8 slave, quint16 address, quint16 value)
{
    QByteArray adu = header(slave, ModbusRequest::WriteSingle);
    appendWord(adu, address);
    appendWord(adu, value);
    return ModbusCrc::append(adu);
}

QByteArray RtuFrame::encodeWriteMultipleReply(quint8 slave, quint16 address, quint16 count)
{
    QByteArray adu = header(slave, ModbusRequest::WriteMultiple);
    appendWord(adu, address);
    appendWord(adu, count);
    return ModbusCrc::append(adu);
}

QByteArray RtuFrame::encodeException(quint8 slave, quint8 function, quint8 code)
{
    QByteArray adu = header(slave, static_cast<quint8>(function | 0x80));
    adu.append(static_cast<char>(code));
    return ModbusCrc::append(adu);
}

QByteArray RtuFrame::encodeRaw(quint8 slave, quint8 function, const QByteArray& data)
{
    return ModbusCrc::append(header(slave, function) + data);
}

QString RtuFrame::toHex(const QByteArray& bytes)
{
    QStringList parts;
    parts.reserve(bytes.size());
    for (char c : bytes)
        parts << hex2(static_cast<quint8>(c));
    return parts.join(QLatin1Char(' '));
}

QByteArray RtuFrame::fromHex(const QString& text)
{
    // Tokens such as "01", "CAh", "0x03" or runs like "0103CA03"; anything else is invalid.
    static const QRegularExpression separators(QStringLiteral("[\\s,;:]+"));
    QString digits;
    for (QString token : text.split(separators, Qt::SkipEmptyParts)) {
        if (token.startsWith(QLatin1String("0x"), Qt::CaseInsensitive))
            token = token.mid(2);
        if (token.endsWith(QLatin1Char('h'), Qt::CaseInsensitive))
            token.chop(1);
        if (token.size() % 2)
            token.prepend(QLatin1Char('0'));
        digits += token;
    }
    QByteArray bytes;
    for (int i = 0; i + 1 < digits.size(); i += 2) {
        bool ok = false;
        const uint value = digits.mid(i, 2).toUInt(&ok, 16);
        if (!ok)
            return QByteArray();
        bytes.append(static_cast<char>(value));
    }
    return bytes;
}

} // namespace opentop
