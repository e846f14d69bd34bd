#include "tests/faultmatrix/BackupValues.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace opentop::faultmatrix {

QVector<Setting> BackupValues::load(const QString& path, QString* error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = QStringLiteral("cannot open %1: %2").arg(path, file.errorString());
        return {};
    }
    QJsonParseError parse;
    const QJsonDocument doc = QJsonDocument::fromJson(file.readAll(), &parse);
    if (!doc.isObject()) {
        *error = QStringLiteral("%1 is not JSON: %2").arg(path, parse.errorString());
        return {};
    }
    QVector<Setting> settings;
    for (const QJsonValue& d : doc.object().value(QStringLiteral("devices")).toArray()) {
        const QJsonObject device = d.toObject();
        for (const QJsonValue& p : device.value(QStringLiteral("parameters")).toArray()) {
            const QJsonObject o = p.toObject();
            Setting s;
            s.slave = device.value(QStringLiteral("slave")).toInt();
            s.family = device.value(QStringLiteral("family")).toString();
            s.name = o.value(QStringLiteral("name")).toString();
            bool ok = false;
            s.address = quint16(o.value(QStringLiteral("address")).toString().toUInt(&ok, 16));
            for (const QJsonValue& r : o.value(QStringLiteral("registers")).toArray())
                s.registers << quint16(r.toInt());
            if (!ok || s.registers.isEmpty()) {
                *error = QStringLiteral("%1: drive %2, %3: no address or registers")
                             .arg(path)
                             .arg(s.slave)
                             .arg(s.name);
                return {};
            }
            settings << s;
        }
    }
    if (settings.isEmpty())
        *error = QStringLiteral("%1 holds no settings").arg(path);
    return settings;
}

QVector<Setting> BackupValues::ofSlave(const QVector<Setting>& settings, int slave)
{
    QVector<Setting> result;
    for (const Setting& s : settings) {
        if (s.slave == slave)
            result << s;
    }
    return result;
}

QVector<int> BackupValues::slaves(const QVector<Setting>& settings)
{
    QVector<int> result;
    for (const Setting& s : settings) {
        if (!result.contains(s.slave))
            result << s.slave;
    }
    return result;
}

} // namespace opentop::faultmatrix
