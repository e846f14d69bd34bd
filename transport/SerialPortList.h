#pragma once

#include <QString>
#include <QVector>

namespace opentop {

// Serial ports the system knows (QSerialPortInfo). Pseudo-terminals (/dev/pts/N, socat links)
// are never listed, so a port field must also accept a typed path.
class SerialPortList
{
public:
    struct Port
    {
        QString systemLocation; // /dev/ttyUSB0, COM3
        QString description;    // FT232R USB UART
        QString manufacturer;   // FTDI
        QString serialNumber;   // A10K3XYZ
        quint16 vendorId = 0;
        quint16 productId = 0;
        bool hasIds = false;

        QString vidPid() const; // "0403:6001", empty without ids
        // "/dev/ttyUSB0 — FT232R USB UART (FTDI, A10K3XYZ)"
        QString oneLine() const;
    };

    // USB adapters first, then by name (COM2 before COM10); Windows names are COMn.
    static QVector<Port> available();
    static bool namedBefore(const QString& a, const QString& b);
    // Shown next to the list: ptys must be typed in.
    static QString typedPathHint();
};

} // namespace opentop
