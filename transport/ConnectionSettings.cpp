#include "transport/ConnectionSettings.h"

#include <QCoreApplication>
#include <QStringList>
#include <algorithm>
#include <cmath>

namespace opentop {

QString ConnectionSettings::validate() const
{
    QStringList problems;
    switch (kind) {
    case Kind::Serial:
        if (port.trimmed().isEmpty())
            problems << QCoreApplication::translate(
                "opentop::Transport",
                "No serial port given: enter a device such as /dev/ttyUSB0 or COM3.");
        if (baud < 1200 || baud > 115200)
            problems << QCoreApplication::translate(
                            "opentop::Transport",
                            "Baud rate %1 is not supported: use 1200–115200 (e.g. 9600, "
                            "19200, 38400, 57600, 115200).")
                            .arg(baud);
        if (parity != 'N' && parity != 'E' && parity != 'O')
            problems << QCoreApplication::translate(
                            "opentop::Transport",
                            "Parity '%1' is not supported: use N (none), E (even) or O (odd).")
                            .arg(QLatin1Char(parity));
        if (dataBits != 7 && dataBits != 8)
            problems << QCoreApplication::translate("opentop::Transport",
                                                    "%1 data bits are not supported: use 7 or 8.")
                            .arg(dataBits);
        if (stopBits != 1 && stopBits != 2)
            problems << QCoreApplication::translate("opentop::Transport",
                                                    "%1 stop bits are not supported: use 1 or 2.")
                            .arg(stopBits);
        if (byteTimeoutMs < 0 || byteTimeoutMs > 10000)
            problems << QCoreApplication::translate(
                            "opentop::Transport",
                            "Byte timeout %1 ms is not allowed: use 1–10000 ms, or 0 to "
                            "derive it from the baud rate.")
                            .arg(byteTimeoutMs);
        if (rs485Name(rs485).isEmpty())
            problems << QCoreApplication::translate(
                            "opentop::Transport",
                            "RS-485 mode %1 is not supported: use off, auto, kernel or rts.")
                            .arg(int(rs485));
        for (auto it = driveLines.begin(); it != driveLines.end(); ++it) {
            const QString invalid = it->validate();
            if (it.key() < 1 || it.key() > 247 || !invalid.isEmpty())
                problems << QCoreApplication::translate(
                                "opentop::Transport",
                                "Line format of machine number %1: %2 Use machine numbers "
                                "1–247.")
                                .arg(it.key())
                                .arg(invalid);
        }
        if (rtsDelayUs < 0 || rtsDelayUs > kMaxRtsDelayUs)
            problems << QCoreApplication::translate(
                            "opentop::Transport",
                            "RTS delay %1 µs is not allowed: use 0–%2 µs (0: the driver's or "
                            "libmodbus' own).")
                            .arg(rtsDelayUs)
                            .arg(kMaxRtsDelayUs);
        break;
    case Kind::Tcp:
        if (host.trimmed().isEmpty())
            problems << QCoreApplication::translate(
                "opentop::Transport",
                "No host given: enter the gateway's address, e.g. 192.168.1.10.");
        if (tcpPort < 1 || tcpPort > 65535)
            problems << QCoreApplication::translate(
                            "opentop::Transport",
                            "TCP port %1 is not allowed: use 1–65535 (Modbus TCP uses 502).")
                            .arg(tcpPort);
        break;
    case Kind::Simulated:
        if (simSpec.trimmed().isEmpty())
            problems << QCoreApplication::translate(
                "opentop::Transport",
                "No simulated devices given: use a list such as dbu200@1,dcpid@7.");
        break;
    }
    if (timeoutMs < 10 || timeoutMs > 10000)
        problems << QCoreApplication::translate("opentop::Transport",
                                                "Timeout %1 ms is not allowed: use 10–10000 ms.")
                        .arg(timeoutMs);
    if (retries < 0 || retries > 10)
        problems << QCoreApplication::translate("opentop::Transport",
                                                "%1 retries are not allowed: use 0–10.")
                        .arg(retries);
    return problems.join(QLatin1Char('\n'));
}

QString ConnectionSettings::describe() const
{
    switch (kind) {
    case Kind::Serial: {
        QString text = QStringLiteral("%1 %2 %3%4%5")
                           .arg(port)
                           .arg(baud)
                           .arg(dataBits)
                           .arg(QLatin1Char(parity))
                           .arg(stopBits);
        const ConnectionSettings defaults;
        if (rs485 != defaults.rs485)
            text += QStringLiteral(" rs485=") + rs485Name(rs485);
        if (rtsHighWhileSending != defaults.rtsHighWhileSending)
            text += QStringLiteral(" rts=low");
        if (rtsDelayUs != defaults.rtsDelayUs)
            text += QStringLiteral(" rts-delay=%1us").arg(rtsDelayUs);
        if (lowLatency != defaults.lowLatency)
            text += QStringLiteral(" low-latency=off");
        if (!driveLines.isEmpty())
            text += QStringLiteral(" drive-format=") + LineFormat::tableText(driveLines);
        return text;
    }
    case Kind::Tcp:
        return QStringLiteral("tcp %1:%2").arg(host).arg(tcpPort);
    case Kind::Simulated:
        return QStringLiteral("sim %1").arg(simSpec);
    }
    return QString();
}

QString ConnectionSettings::rs485Name(Rs485 mode)
{
    switch (mode) {
    case Rs485::Off:
        return QStringLiteral("off");
    case Rs485::Auto:
        return QStringLiteral("auto");
    case Rs485::Kernel:
        return QStringLiteral("kernel");
    case Rs485::Rts:
        return QStringLiteral("rts");
    }
    return QString();
}

bool ConnectionSettings::rs485FromName(const QString& name, Rs485* mode)
{
    for (Rs485 m : {Rs485::Off, Rs485::Auto, Rs485::Kernel, Rs485::Rts}) {
        if (name.trimmed().compare(rs485Name(m), Qt::CaseInsensitive) == 0) {
            *mode = m;
            return true;
        }
    }
    return false;
}

LineFormat ConnectionSettings::line() const
{
    return LineFormat{baud, parity, dataBits, stopBits};
}

void ConnectionSettings::setLine(const LineFormat& format)
{
    baud = format.baud;
    parity = format.parity;
    dataBits = format.dataBits;
    stopBits = format.stopBits;
}

double ConnectionSettings::charTimeMs() const
{
    const int bits = 1 + dataBits + (parity == 'N' ? 0 : 1) + stopBits;
    const int rate = baud > 0 ? baud : 19200;
    return 1000.0 * bits / rate;
}

int ConnectionSettings::effectiveByteTimeoutMs() const
{
    if (byteTimeoutMs > 0)
        return byteTimeoutMs;
    if (kind == Kind::Tcp)
        return timeoutMs; // a TCP reply may arrive in several segments
    // Modbus allows 1.5 characters between bytes, but USB adapters deliver in chunks (FTDI's
    // latency timer is 16 ms by default): allow several characters and at least 20 ms.
    return std::max(20, int(std::ceil(charTimeMs() * 8)));
}

} // namespace opentop
