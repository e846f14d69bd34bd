#pragma once

#include <QByteArray>
#include <QMap>
#include <QString>

namespace opentop {

// The object list of a 0x2B / 0x0E read device identification reply. `parse` reads what
// ModbusResult::rawData holds for such a request; `encode` builds it (for the simulator).
struct DeviceIdentification
{
    quint8 readCode = 1;      // 1 basic, 2 regular, 3 extended, 4 one object
    quint8 conformity = 0x01; // conformity level the device reports
    bool moreFollows = false; // the device needs another request from nextObjectId
    quint8 nextObjectId = 0;
    QMap<quint8, QByteArray> objects; // 0 vendor, 1 product code, 2 revision, ...

    // False when `rawData` is not a complete, consistent object list.
    static bool parse(const QByteArray& rawData, DeviceIdentification* out);
    QByteArray encode() const; // bytes after the function code, starting with 0x0E
    static QString objectName(quint8 id);
    QString text(quint8 id) const; // object value as Latin-1 text, trimmed
};

} // namespace opentop
