#include "transport/ModbusResult.h"

#include <QCoreApplication>

namespace opentop {

QString modbusErrorName(ModbusError error)
{
    switch (error) {
    case ModbusError::Ok:
        return QCoreApplication::translate("opentop::Transport", "ok");
    case ModbusError::Timeout:
        return QCoreApplication::translate("opentop::Transport", "timeout");
    case ModbusError::CrcError:
        return QCoreApplication::translate("opentop::Transport", "CRC error");
    case ModbusError::WrongSlave:
        return QCoreApplication::translate("opentop::Transport", "reply from wrong slave");
    case ModbusError::Exception:
        return QCoreApplication::translate("opentop::Transport", "exception");
    case ModbusError::MalformedReply:
        return QCoreApplication::translate("opentop::Transport", "malformed reply");
    case ModbusError::PortError:
        return QCoreApplication::translate("opentop::Transport", "port error");
    case ModbusError::NotConnected:
        return QCoreApplication::translate("opentop::Transport", "not connected");
    case ModbusError::InvalidRequest:
        return QCoreApplication::translate("opentop::Transport", "invalid request");
    case ModbusError::Cancelled:
        return QCoreApplication::translate("opentop::Transport", "cancelled");
    }
    return QString();
}

QString modbusExceptionName(quint8 code)
{
    switch (code) {
    case 0x01:
        return QCoreApplication::translate("opentop::Transport", "Illegal function");
    case 0x02:
        return QCoreApplication::translate("opentop::Transport", "Illegal data address");
    case 0x03:
        return QCoreApplication::translate("opentop::Transport", "Illegal data value");
    case 0x04:
        return QCoreApplication::translate("opentop::Transport", "Slave device failure");
    case 0x05:
        return QCoreApplication::translate("opentop::Transport", "Acknowledge (processing)");
    case 0x06:
        return QCoreApplication::translate("opentop::Transport", "Slave device busy");
    case 0x07:
        return QCoreApplication::translate("opentop::Transport", "Negative acknowledge");
    case 0x08:
        return QCoreApplication::translate("opentop::Transport", "Memory parity error");
    case 0x0A:
        return QCoreApplication::translate("opentop::Transport", "Gateway path unavailable");
    case 0x0B:
        return QCoreApplication::translate("opentop::Transport",
                                           "Gateway target device failed to respond");
    // Extended codes of the DC motor controller (its manual, table 3.2).
    case 0x40:
        return QCoreApplication::translate("opentop::Transport", "Prohibited action");
    case 0xFF:
        return QCoreApplication::translate("opentop::Transport", "Undefined error");
    default:
        return QCoreApplication::translate("opentop::Transport", "Unknown exception");
    }
}

QString ModbusResult::errorText() const
{
    switch (error) {
    case ModbusError::Ok:
        return modbusErrorName(error);
    case ModbusError::Exception:
        return QCoreApplication::translate("opentop::Transport", "exception %1 %2")
            .arg(QString::number(exceptionCode, 16).rightJustified(2, QLatin1Char('0')).toUpper(),
                 modbusExceptionName(exceptionCode));
    case ModbusError::Timeout:
        if (attempts > 1)
            return QCoreApplication::translate("opentop::Transport", "timeout after %1 attempts")
                .arg(attempts);
        return QCoreApplication::translate("opentop::Transport", "timeout (no reply)");
    default:
        break;
    }
    QString text = modbusErrorName(error);
    if (!message.isEmpty())
        text += QStringLiteral(": ") + message;
    if (attempts > 1 && (error == ModbusError::CrcError || error == ModbusError::WrongSlave))
        text += QCoreApplication::translate("opentop::Transport", " (%1 attempts)").arg(attempts);
    return text;
}

} // namespace opentop
