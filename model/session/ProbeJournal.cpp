#include "model/session/ProbeJournal.h"

#include "model/io/OutputFile.h"

#include "model/ModelLog.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLockFile>
#include <QStandardPaths>

namespace opentop {

namespace {

QString keyOf(const QString& port, int slave)
{
    return QStringLiteral("%1#%2").arg(port).arg(slave);
}

QJsonObject readAll(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    QJsonParseError parse;
    const QJsonDocument doc = QJsonDocument::fromJson(file.readAll(), &parse);
    if (!doc.isObject())
        qCWarning(lcModel).noquote()
            << ProbeJournal::tr("%1 is not a probe journal (%2): ignored; a probe interrupted "
                                "before may have left its value on a drive")
                   .arg(path, parse.errorString());
    return doc.object();
}

bool writeAll(const QString& path, const QJsonObject& entries, QString* error)
{
    if (!QDir().mkpath(QFileInfo(path).absolutePath())) {
        *error = ProbeJournal::tr("cannot create the folder of %1").arg(path);
        return false;
    }
    return OutputFile::write(path, QJsonDocument(entries).toJson(QJsonDocument::Indented), error);
}

} // namespace

ProbeJournal::ProbeJournal(const QString& path)
    : m_path(path)
{
}

QString ProbeJournal::defaultPath()
{
    return QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation) +
           QStringLiteral("/opentop/probe-journal.json");
}

std::optional<ProbeJournal::Entry> ProbeJournal::pending(const QString& port, int slave) const
{
    const QJsonObject o = readAll(m_path).value(keyOf(port, slave)).toObject();
    if (o.isEmpty())
        return std::nullopt;
    return Entry{o.value(QStringLiteral("parameter")).toString(),
                 o.value(QStringLiteral("original")).toString(),
                 o.value(QStringLiteral("probe")).toString()};
}

bool ProbeJournal::begin(const QString& port, int slave, const Entry& entry, QString* error)
{
    // The window and the command line may probe drives on two ports at once: one writer at a
    // time, or one of them would drop the other's entry.
    QDir().mkpath(QFileInfo(m_path).absolutePath());
    QLockFile lock(m_path + QStringLiteral(".lock"));
    if (!lock.tryLock(2000)) {
        *error = tr("%1 is locked by another program").arg(m_path);
        return false;
    }
    QJsonObject all = readAll(m_path);
    all.insert(keyOf(port, slave), QJsonObject{{QStringLiteral("parameter"), entry.parameter},
                                               {QStringLiteral("original"), entry.original},
                                               {QStringLiteral("probe"), entry.probe}});
    return writeAll(m_path, all, error);
}

bool ProbeJournal::end(const QString& port, int slave, QString* error)
{
    QLockFile lock(m_path + QStringLiteral(".lock"));
    if (!lock.tryLock(2000)) {
        *error = tr("%1 is locked by another program").arg(m_path);
        return false;
    }
    QJsonObject all = readAll(m_path);
    if (!all.contains(keyOf(port, slave)))
        return true;
    all.remove(keyOf(port, slave));
    return writeAll(m_path, all, error);
}

} // namespace opentop
