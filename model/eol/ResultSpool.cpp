#include "model/eol/ResultSpool.h"

#include "model/ModelLog.h"
#include "model/eol/ResultUrl.h"
#include "model/eol/UnitRecordJson.h"

#include <QCryptographicHash>
#include <QDir>
#include <QJsonDocument>
#include <QSqlError>
#include <QSqlQuery>
#include <QStandardPaths>
#include <atomic>

namespace opentop {

namespace {

std::atomic<int> spoolCounter{0};

QString kindName(ResultSpool::Kind kind)
{
    return kind == ResultSpool::Kind::Begin ? QStringLiteral("begin") : QStringLiteral("finish");
}

// QtSql binds a null QString as NULL; the columns are NOT NULL.
QString text(const QString& s)
{
    return s.isNull() ? QString(QLatin1String("")) : s;
}

} // namespace

ResultSpool::~ResultSpool()
{
    if (m_db.isOpen())
        m_db.close();
    m_db = QSqlDatabase();
    if (!m_connection.isEmpty())
        QSqlDatabase::removeDatabase(m_connection);
}

QString ResultSpool::defaultFolder()
{
    // Beside the default results file, the same for every program of the station (the window
    // and the command line send each other's entries).
    return QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation) +
           QStringLiteral("/opentop/spool");
}

std::unique_ptr<ResultSpool> ResultSpool::open(const QString& folder, const QString& databaseUrl,
                                               QString* error)
{
    // One file per database, named by its address without the password: an entry goes only to
    // the database it was meant for.
    QString display = databaseUrl;
    if (const auto parsed = ResultUrl::parse(databaseUrl, nullptr))
        display = parsed->displayText();
    const QByteArray key =
        QCryptographicHash::hash(display.toUtf8(), QCryptographicHash::Sha256).toHex().left(16);
    std::unique_ptr<ResultSpool> self(new ResultSpool);
    self->m_path =
        folder + QStringLiteral("/results-") + QString::fromLatin1(key) + QStringLiteral(".spool");
    auto fail = [&](const QString& why) -> std::unique_ptr<ResultSpool> {
        if (error)
            *error =
                tr("the station's spool %1: %2").arg(QDir::toNativeSeparators(self->m_path), why);
        return nullptr;
    };
    if (!QDir().mkpath(folder))
        return fail(tr("its folder cannot be made"));
    self->m_connection = QStringLiteral("opentop-spool-%1").arg(++spoolCounter);
    self->m_db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), self->m_connection);
    self->m_db.setDatabaseName(self->m_path);
    self->m_db.setConnectOptions(QStringLiteral("QSQLITE_BUSY_TIMEOUT=10000"));
    if (!self->m_db.open())
        return fail(self->m_db.lastError().text());
    QSqlQuery q(self->m_db);
    // FULL: an entry the screen calls saved survives a power cut.
    for (const char* sql :
         {"PRAGMA journal_mode=WAL", "PRAGMA synchronous=FULL",
          "CREATE TABLE IF NOT EXISTS spool (seq INTEGER PRIMARY KEY AUTOINCREMENT,"
          " kind TEXT NOT NULL, unit_id TEXT NOT NULL, lease TEXT NOT NULL,"
          " queued_utc TEXT NOT NULL, record TEXT NOT NULL)"}) {
        if (!q.exec(QString::fromLatin1(sql)))
            return fail(q.lastError().text());
    }
    return self;
}

bool ResultSpool::append(Kind kind, const UnitRecord& record, const QString& lease, QString* error)
{
    QSqlQuery q(m_db);
    q.prepare(QStringLiteral("INSERT INTO spool (kind, unit_id, lease, queued_utc, record)"
                             " VALUES (?, ?, ?, ?, ?)"));
    q.addBindValue(kindName(kind));
    q.addBindValue(text(record.id));
    q.addBindValue(text(lease));
    q.addBindValue(UnitRecordJson::timeText(QDateTime::currentDateTimeUtc()));
    q.addBindValue(QString::fromUtf8(UnitRecordJson::toBytes(record)));
    if (!q.exec()) {
        if (error)
            *error = tr("the station's spool %1: %2")
                         .arg(QDir::toNativeSeparators(m_path), q.lastError().text());
        return false;
    }
    qCInfo(lcModel) << "results spool: kept" << kindName(kind) << "of unit" << record.serial
                    << record.id;
    return true;
}

std::optional<ResultSpool::Entry> ResultSpool::oldest(QString* error)
{
    QSqlQuery q(m_db);
    if (!q.exec(
            QStringLiteral("SELECT seq, kind, lease, record FROM spool ORDER BY seq LIMIT 1"))) {
        if (error)
            *error = q.lastError().text();
        return std::nullopt;
    }
    if (!q.next())
        return std::nullopt;
    Entry e;
    e.seq = q.value(0).toLongLong();
    e.kind = q.value(1).toString() == QLatin1String("begin") ? Kind::Begin : Kind::Finish;
    e.lease = q.value(2).toString();
    QString why;
    const auto record = UnitRecordJson::fromBytes(q.value(3).toString().toUtf8(), &why);
    if (!record) {
        if (error)
            *error = tr("the station's spool %1: entry %2 cannot be read (%3)")
                         .arg(QDir::toNativeSeparators(m_path))
                         .arg(e.seq)
                         .arg(why);
        return std::nullopt;
    }
    e.record = *record;
    return e;
}

bool ResultSpool::remove(qint64 seq, QString* error)
{
    QSqlQuery q(m_db);
    q.prepare(QStringLiteral("DELETE FROM spool WHERE seq = ?"));
    q.addBindValue(seq);
    if (q.exec())
        return true;
    if (error)
        *error = q.lastError().text();
    return false;
}

int ResultSpool::count(QString* error)
{
    QSqlQuery q(m_db);
    if (q.exec(QStringLiteral("SELECT COUNT(*) FROM spool")) && q.next())
        return q.value(0).toInt();
    if (error)
        *error = q.lastError().text();
    return -1;
}

} // namespace opentop
