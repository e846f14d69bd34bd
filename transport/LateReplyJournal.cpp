#include "transport/LateReplyJournal.h"

#include "transport/TransportLog.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSaveFile>
#ifndef Q_OS_WIN
#include <unistd.h>
#endif

namespace opentop {

LateReplyJournal::LateReplyJournal(const QString& device, const QString& directory)
{
    QString name = device;
    name.replace(QLatin1Char('/'), QLatin1Char('_'));
    m_path = QDir(directory).filePath(QStringLiteral("late") + name);
}

QString LateReplyJournal::defaultDirectory()
{
    const QString custom = qEnvironmentVariable("OPENTOP_LATE_JOURNAL_DIR");
    if (!custom.isEmpty())
        return custom;
#ifdef Q_OS_WIN // the temporary folder is the user's own there
    return QDir::temp().filePath(QStringLiteral("opentop-late"));
#else
    return QDir::temp().filePath(QStringLiteral("opentop-late-%1").arg(::getuid()));
#endif
}

void LateReplyJournal::write(const QVector<Entry>& entries) const
{
    if (entries.isEmpty()) {
        QFile::remove(m_path);
        return;
    }
    const QString directory = QFileInfo(m_path).absolutePath();
    // The user's own directory: another user's journal could only make us check more, but it
    // is not theirs to write.
    if (!QDir().mkpath(directory) ||
        !QFile::setPermissions(directory, QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner)) {
        qCWarning(lcTransport) << "late-reply journal: cannot use" << directory;
        return;
    }
    QSaveFile file(m_path);
    if (!file.open(QIODevice::WriteOnly)) {
        qCWarning(lcTransport) << "late-reply journal:" << file.errorString();
        return;
    }
    for (const Entry& e : entries)
        file.write(QByteArray::number(e.slave) + ' ' + QByteArray::number(e.untilMs) + ' ' +
                   QByteArray::number(e.function) + ' ' + QByteArray::number(e.count) + '\n');
    if (!file.commit())
        qCWarning(lcTransport) << "late-reply journal:" << file.errorString();
}

QVector<LateReplyJournal::Entry> LateReplyJournal::take(qint64 nowMs) const
{
    QVector<Entry> entries;
    QFile file(m_path);
    if (!file.open(QIODevice::ReadOnly))
        return entries;
    // Small by construction; anything else is not ours and is ignored.
    const QList<QByteArray> lines = file.read(64 * 1024).split('\n');
    file.close();
    QFile::remove(m_path);
    for (const QByteArray& line : lines) {
        const QList<QByteArray> fields = line.split(' ');
        if (fields.size() != 4)
            continue;
        bool slaveOk = false;
        bool untilOk = false;
        bool functionOk = false;
        bool countOk = false;
        const uint slave = fields[0].toUInt(&slaveOk);
        const qint64 until = fields[1].toLongLong(&untilOk);
        const uint function = fields[2].toUInt(&functionOk);
        const int count = fields[3].toInt(&countOk);
        // Modbus functions are 1..127; no request reads more than 2000 coils.
        if (slaveOk && untilOk && functionOk && countOk && slave >= 1 && slave <= 247 &&
            until > nowMs && until - nowMs < 60 * 1000 && function <= 127 && count >= 0 &&
            count <= 2000 && (function != 0 || count == 0))
            entries.append(Entry{quint8(slave), until, quint8(function), count});
    }
    return entries;
}

} // namespace opentop
