#include "bus/BusMemory.h"

#include "bus/BusDrives.h"

#include <QCoreApplication>
#include <QSettings>
#include <QStringList>

namespace opentop {

namespace {

QString settingsGroup(const QString& key)
{
    // Slashes separate QSettings groups: the key is stored encoded.
    return QStringLiteral("busMemory/") +
           QString::fromLatin1(key.toUtf8().toBase64(QByteArray::Base64UrlEncoding |
                                                     QByteArray::OmitTrailingEquals));
}

} // namespace

QString BusMemory::key(const ConnectionSettings& settings)
{
    switch (settings.kind) {
    case ConnectionSettings::Kind::Serial:
        return QStringLiteral("serial:") + settings.port;
    case ConnectionSettings::Kind::Tcp:
        return QStringLiteral("tcp:%1:%2").arg(settings.host).arg(settings.tcpPort);
    case ConnectionSettings::Kind::Simulated:
        return QStringLiteral("sim:") + settings.simSpec;
    }
    return {};
}

QString BusMemory::placeText(const ConnectionSettings& settings)
{
    switch (settings.kind) {
    case ConnectionSettings::Kind::Serial:
        return settings.port;
    case ConnectionSettings::Kind::Tcp:
        return QStringLiteral("%1:%2").arg(settings.host).arg(settings.tcpPort);
    case ConnectionSettings::Kind::Simulated:
        return QCoreApplication::translate("opentop::BusMemory", "the simulated bus");
    }
    return {};
}

QVector<BusMemory::Drive> BusMemory::present(const BusDrives& drives)
{
    QVector<Drive> out;
    for (int slave : drives.slaves()) {
        const DeviceInfo info = drives.info(slave);
        if (info.state != DeviceInfo::State::Present || info.family.isEmpty())
            continue;
        out << Drive{slave, info.variant.isEmpty() ? info.family : info.variant, info.model,
                     info.line};
    }
    return out;
}

void BusMemory::save(const QString& key, const BusDrives& drives)
{
    QSettings settings;
    settings.remove(settingsGroup(key));
    settings.beginWriteArray(settingsGroup(key));
    int index = 0;
    for (const Drive& d : present(drives)) {
        settings.setArrayIndex(index++);
        settings.setValue(QStringLiteral("slave"), d.slave);
        settings.setValue(QStringLiteral("type"), d.type);
        settings.setValue(QStringLiteral("model"), d.model);
        if (d.line.isSet())
            settings.setValue(QStringLiteral("line"), d.line.token());
    }
    settings.endArray();
}

QVector<BusMemory::Drive> BusMemory::load(const QString& key)
{
    QSettings settings;
    QVector<Drive> out;
    const int count = settings.beginReadArray(settingsGroup(key));
    for (int i = 0; i < count; ++i) {
        settings.setArrayIndex(i);
        Drive d;
        d.slave = settings.value(QStringLiteral("slave")).toInt();
        d.type = settings.value(QStringLiteral("type")).toString();
        d.model = settings.value(QStringLiteral("model")).toString();
        const QString line = settings.value(QStringLiteral("line")).toString();
        if (!line.isEmpty())
            d.line = LineFormat::parse(line, 0).value_or(LineFormat());
        if (d.slave >= 1 && d.slave <= 247 && !d.type.isEmpty())
            out << d;
    }
    settings.endArray();
    return out;
}

void BusMemory::forget(const QString& key)
{
    QSettings().remove(settingsGroup(key));
}

QHash<int, QString> BusMemory::types(const QVector<Drive>& drives)
{
    QHash<int, QString> out;
    for (const Drive& d : drives)
        out.insert(d.slave, d.type);
    return out;
}

QMap<int, LineFormat> BusMemory::lines(const QVector<Drive>& drives)
{
    QMap<int, LineFormat> out;
    for (const Drive& d : drives)
        if (d.line.isSet())
            out.insert(d.slave, d.line);
    return out;
}

QString BusMemory::listText(const QVector<Drive>& drives)
{
    QStringList parts;
    for (const Drive& d : drives)
        parts << (d.model.isEmpty() ? QString::number(d.slave)
                                    : QStringLiteral("%1 (%2)").arg(d.slave).arg(d.model)) +
                     (d.line.isSet() ? QStringLiteral(" %1").arg(d.line.text()) : QString());
    return parts.join(QStringLiteral(", "));
}

} // namespace opentop
