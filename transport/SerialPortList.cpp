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
        port.systemLocation = info.systemLocation();
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
        return a.systemLocation < b.systemLocation;
    });
    return ports;
}

QString SerialPortList::typedPathHint()
{
    return QCoreApplication::translate(
        "opentop::Transport",
        "Pseudo-terminals (e.g. /dev/pts/3 or a socat link) are not listed: type their path.");
}

} // namespace opentop
