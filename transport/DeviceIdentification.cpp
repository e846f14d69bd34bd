#include "transport/DeviceIdentification.h"

#include <QCoreApplication>

namespace opentop {

bool DeviceIdentification::parse(const QByteArray& rawData, DeviceIdentification* out)
{
    // 0E, read code, conformity, more follows, next object id, object count, objects...
    if (rawData.size() < 6 || quint8(rawData[0]) != 0x0E)
        return false;
    DeviceIdentification id;
    id.readCode = quint8(rawData[1]);
    id.conformity = quint8(rawData[2]);
    id.moreFollows = quint8(rawData[3]) == 0xFF;
    id.nextObjectId = quint8(rawData[4]);
    const int count = quint8(rawData[5]);
    int pos = 6;
    for (int i = 0; i < count; ++i) {
        if (rawData.size() < pos + 2)
            return false;
        const quint8 objectId = quint8(rawData[pos]);
        const int length = quint8(rawData[pos + 1]);
        if (rawData.size() < pos + 2 + length)
            return false;
        id.objects.insert(objectId, rawData.mid(pos + 2, length));
        pos += 2 + length;
    }
    if (pos != rawData.size())
        return false;
    *out = id;
    return true;
}

QByteArray DeviceIdentification::encode() const
{
    QByteArray bytes;
    bytes.append(char(0x0E));
    bytes.append(char(readCode));
    bytes.append(char(conformity));
    bytes.append(char(moreFollows ? 0xFF : 0x00));
    bytes.append(char(nextObjectId));
    bytes.append(char(objects.size()));
    for (auto it = objects.cbegin(); it != objects.cend(); ++it) {
        bytes.append(char(it.key()));
        bytes.append(char(it.value().size()));
        bytes.append(it.value());
    }
    return bytes;
}

QString DeviceIdentification::objectName(quint8 id)
{
    switch (id) {
    case 0x00:
        return QCoreApplication::translate("opentop::Transport", "Vendor name");
    case 0x01:
        return QCoreApplication::translate("opentop::Transport", "Product code");
    case 0x02:
        return QCoreApplication::translate("opentop::Transport", "Revision");
    case 0x03:
        return QCoreApplication::translate("opentop::Transport", "Vendor URL");
    case 0x04:
        return QCoreApplication::translate("opentop::Transport", "Product name");
    case 0x05:
        return QCoreApplication::translate("opentop::Transport", "Model name");
    case 0x06:
        return QCoreApplication::translate("opentop::Transport", "User application name");
    default:
        return QCoreApplication::translate("opentop::Transport", "Object 0x%1")
            .arg(QString::number(id, 16).rightJustified(2, QLatin1Char('0')).toUpper());
    }
}

QString DeviceIdentification::text(quint8 id) const
{
    return QString::fromLatin1(objects.value(id)).trimmed();
}

} // namespace opentop
