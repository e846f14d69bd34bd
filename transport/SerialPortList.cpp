#include "transport/SerialPortList.h"

#include <QCoreApplication>
#include <QSerialPortInfo>
#include <QStringList>
#include <algorithm>

namespace opentop {

QString SerialPortList::Port::vidPid() const
{
    if (!hasIds)
        return QString();
    return QStringLiteral("%1:%2")
        .arg(vendorId, 4, 16, QLatin1Char('0'))
        .arg(productId, 4, 16, QLatin1Char('0'));
}

QString SerialPortList::Port::oneLine() const
{
    QString line = systemLocation;
    if (!description.isEmpty())
        line += QStringLiteral(" — ") + description;
    QStringList details;
    if (!manufacturer.isEmpty())
        details << manufacturer;
    if (!serialNumber.isEmpty())
        details << serialNumber;
    if (details.isEmpty() && hasIds)
        details << vidPid();
    if (!details.isEmpty())
        line += QStringLiteral(" (") + details.join(QStringLiteral(", ")) + QLatin1Char(')');
    return line;
}

QVector<SerialPortList::Port> SerialPortList::available()
{
    QVector<Port> ports;
    const auto infos = QSerialPortInfo::availablePorts();
    for (const QSerialPortInfo& info : infos) {
        Port port;
#ifdef Q_OS_WIN
        port.systemLocation = info.portName(); // COM3, as Device Manager and users name it
#else
        port.systemLocation = info.systemLocation();
#endif
        port.description = info.description();
        port.manufacturer = info.manufacturer();
        port.serialNumber = info.serialNumber();
        port.hasIds = info.hasVendorIdentifier() && info.hasProductIdentifier();
        if (port.hasIds) {
            port.vendorId = info.vendorIdentifier();
            port.productId = info.productIdentifier();
        }
        ports.append(port);
    }
    // USB adapters (with ids) first: they are what a commissioning engineer plugs in.
    std::stable_sort(ports.begin(), ports.end(), [](const Port& a, const Port& b) {
        if (a.hasIds != b.hasIds)
            return a.hasIds;
        return namedBefore(a.systemLocation, b.systemLocation);
    });
    return ports;
}

bool SerialPortList::namedBefore(const QString& a, const QString& b)
{
    // COM2 before COM10, /dev/ttyUSB2 before /dev/ttyUSB10: by the name, then its number.
    const auto split = [](const QString& name) {
        int digits = int(name.size());
        while (digits > 0 && name.at(digits - 1).isDigit())
            --digits;
        return std::make_pair(name.left(digits), name.mid(digits));
    };
    const auto [stemA, numberA] = split(a);
    const auto [stemB, numberB] = split(b);
    if (stemA != stemB)
        return stemA < stemB;
    if (numberA.size() != numberB.size())
        return numberA.size() < numberB.size();
    return numberA < numberB;
}

QString SerialPortList::typedPathHint()
{
#ifdef Q_OS_WIN
    return QCoreApplication::translate(
        "opentop::Transport",
        "An adapter missing here has no driver: see Device Manager, Ports (COM & LPT). A port "
        "can also be typed, e.g. COM12.");
#else
    return QCoreApplication::translate(
        "opentop::Transport",
        "Pseudo-terminals (e.g. /dev/pts/3 or a socat link) are not listed: type their path.");
#endif
}

} // namespace opentop
