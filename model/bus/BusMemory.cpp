#include "model/bus/BusMemory.h"

#include "model/bus/BusDrives.h"
#include "model/bus/DriveName.h"
#include "model/session/DeviceSession.h"
#include "model/session/StoreTracker.h"

#include <QCoreApplication>
#include <QSettings>
#include <QStringList>
#include <algorithm>
#include <memory>

namespace opentop {

namespace {

QString encoded(const QString& key)
{
    // Slashes separate QSettings groups: the key is stored encoded.
    return QString::fromLatin1(
        key.toUtf8().toBase64(QByteArray::Base64UrlEncoding | QByteArray::OmitTrailingEquals));
}

QString settingsGroup(const QString& key)
{
    return QStringLiteral("busMemory/") + encoded(key);
}

QString savedAtEntry(const QString& key)
{
    return QStringLiteral("busMemorySaved/") + encoded(key);
}

QString namesGroup(const QString& key)
{
    return QStringLiteral("busNames/") + encoded(key);
}

QString unstoredEntry(const QString& key, int slave)
{
    return QStringLiteral("busUnstored/") + encoded(key) + QLatin1Char('/') +
           QString::number(slave);
}

// The window's settings ("OpenTOP", "OpenTOP"), also from the command line, which names no
// organisation of its own: both programs remember one bus. A program that names its
// organisation (the window, the tests) uses its own settings.
std::unique_ptr<QSettings> store()
{
    if (QCoreApplication::organizationName().isEmpty())
        return std::make_unique<QSettings>(QStringLiteral("OpenTOP"), QStringLiteral("OpenTOP"));
    return std::make_unique<QSettings>();
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
                     drives.name(slave), info.line};
    }
    return out;
}

QVector<BusMemory::Drive> BusMemory::present(const QVector<DeviceInfo>& devices)
{
    QVector<Drive> out;
    for (const DeviceInfo& info : devices) {
        if (info.state != DeviceInfo::State::Present || info.family.isEmpty())
            continue;
        out << Drive{info.slave, info.variant.isEmpty() ? info.family : info.variant, info.model,
                     QString(), info.line};
    }
    return out;
}

void BusMemory::save(const QString& key, const BusDrives& drives)
{
    save(key, present(drives));
}

void BusMemory::update(const QString& key, int from, int to, const QVector<Drive>& found)
{
    QVector<Drive> drives;
    for (const Drive& d : load(key)) {
        if (d.slave < from || d.slave > to)
            drives << d;
    }
    drives += found;
    std::sort(drives.begin(), drives.end(),
              [](const Drive& a, const Drive& b) { return a.slave < b.slave; });
    save(key, drives);
}

QDateTime BusMemory::savedAt(const QString& key)
{
    return store()->value(savedAtEntry(key)).toDateTime();
}

void BusMemory::save(const QString& key, const QVector<Drive>& drives)
{
    const std::unique_ptr<QSettings> kept = store();
    QSettings& settings = *kept;
    settings.remove(settingsGroup(key));
    settings.setValue(savedAtEntry(key), QDateTime::currentDateTimeUtc());
    settings.beginWriteArray(settingsGroup(key));
    int index = 0;
    for (const Drive& d : drives) {
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
    const std::unique_ptr<QSettings> kept = store();
    QSettings& settings = *kept;
    const QHash<int, QString> named = names(key);
    QVector<Drive> out;
    const int count = settings.beginReadArray(settingsGroup(key));
    for (int i = 0; i < count; ++i) {
        settings.setArrayIndex(i);
        Drive d;
        d.slave = settings.value(QStringLiteral("slave")).toInt();
        d.type = settings.value(QStringLiteral("type")).toString();
        d.model = settings.value(QStringLiteral("model")).toString();
        d.name = named.value(d.slave);
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
    const std::unique_ptr<QSettings> settings = store();
    settings->remove(settingsGroup(key));
    settings->remove(savedAtEntry(key));
}

QHash<int, QString> BusMemory::names(const QString& key)
{
    const std::unique_ptr<QSettings> settings = store();
    settings->beginGroup(namesGroup(key));
    QHash<int, QString> out;
    for (const QString& k : settings->childKeys()) {
        bool ok = false;
        const int slave = k.toInt(&ok);
        const QString name = settings->value(k).toString();
        if (ok && slave >= 1 && slave <= 247 && !name.trimmed().isEmpty() &&
            DriveName::problem(name).isEmpty())
            out.insert(slave, DriveName::cleaned(name));
    }
    settings->endGroup();
    return out;
}

QStringList BusMemory::unstored(const QString& key, int slave)
{
    return store()->value(unstoredEntry(key, slave)).toStringList();
}

void BusMemory::keep(const QString& key, DeviceSession* session)
{
    StoreTracker* tracker = StoreTracker::of(session);
    if (!tracker || tracker->property("keptFor").toString() == key)
        return;
    tracker->setProperty("keptFor", key);
    const int slave = session->slave();
    // Only store commands the drive's profile has (a settings file edited by hand).
    QStringList known;
    for (const QString& c : unstored(key, slave)) {
        if (session->profile().parameter(c))
            known << c;
    }
    tracker->seed(known);
    QObject::connect(tracker, &StoreTracker::changed, tracker, [key, slave, tracker] {
        const std::unique_ptr<QSettings> settings = store();
        if (tracker->unstored().isEmpty())
            settings->remove(unstoredEntry(key, slave));
        else
            settings->setValue(unstoredEntry(key, slave), tracker->unstored());
    });
}

void BusMemory::setName(const QString& key, int slave, const QString& name)
{
    const std::unique_ptr<QSettings> settings = store();
    const QString entry = namesGroup(key) + QLatin1Char('/') + QString::number(slave);
    if (DriveName::cleaned(name).isEmpty())
        settings->remove(entry);
    else
        settings->setValue(entry, DriveName::cleaned(name));
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
    for (const Drive& d : drives) {
        QString what = d.model;
        if (!d.name.isEmpty())
            what = d.model.isEmpty() ? d.name : QStringLiteral("%1, %2").arg(d.name, d.model);
        parts << (what.isEmpty() ? QString::number(d.slave)
                                 : QStringLiteral("%1 (%2)").arg(d.slave).arg(what)) +
                     (d.line.isSet() ? QStringLiteral(" %1").arg(d.line.text()) : QString());
    }
    return parts.join(QStringLiteral(", "));
}

} // namespace opentop
