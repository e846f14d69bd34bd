#include "model/eol/ResultDatabase.h"

#include "model/ModelLog.h"
#include "model/eol/ResultSchema.h"

#include <QElapsedTimer>
#include <QSqlError>
#include <QSqlQuery>
#include <QThread>
#include <atomic>

namespace opentop {

namespace {

std::atomic<int> connectionCounter{0};

} // namespace

ResultDatabase::~ResultDatabase()
{
    if (db_.isOpen())
        db_.close();
    db_ = QSqlDatabase(); // the last handle must be gone before the connection is removed
    if (!connectionName_.isEmpty())
        QSqlDatabase::removeDatabase(connectionName_);
}

std::unique_ptr<ResultDatabase> ResultDatabase::open(const QString& url, QString* error,
                                                     int schemaVersion)
{
    const auto parsed = ResultUrl::parse(url, error);
    if (!parsed)
        return nullptr;
    return open(*parsed, error, schemaVersion);
}

std::unique_ptr<ResultDatabase> ResultDatabase::open(const ResultUrl& url, QString* error,
                                                     int schemaVersion)
{
    std::unique_ptr<ResultDatabase> self(new ResultDatabase);
    self->url_ = url;
    auto fail = [&](const QString& why) -> std::unique_ptr<ResultDatabase> {
        if (error)
            *error = tr("results database %1: %2").arg(url.displayText(), why);
        return nullptr;
    };
    if (!QSqlDatabase::isDriverAvailable(url.driverName()))
        return fail(tr("the Qt SQL driver %1 is not installed (Debian: %2)")
                        .arg(url.driverName(), url.engine == ResultUrl::Engine::Sqlite
                                                   ? QStringLiteral("libqt6sql6-sqlite")
                                                   : QStringLiteral("libqt6sql6-psql")));
    self->connectionName_ = QStringLiteral("opentop-results-%1").arg(++connectionCounter);
    self->db_ = QSqlDatabase::addDatabase(url.driverName(), self->connectionName_);
    QSqlDatabase& db = self->db_;
    if (url.engine == ResultUrl::Engine::Sqlite) {
        db.setDatabaseName(url.path);
        db.setConnectOptions(QStringLiteral("QSQLITE_BUSY_TIMEOUT=%1").arg(kBusyTimeoutMs));
    } else {
        db.setHostName(url.host);
        if (url.port > 0)
            db.setPort(url.port);
        db.setUserName(url.user);
        db.setPassword(url.password);
        db.setDatabaseName(url.database);
        db.setConnectOptions(url.options);
    }
    if (!db.open())
        return fail(db.lastError().text());
    QString why;
    if (!self->configure(&why))
        return fail(why);
    const int target = schemaVersion > 0 ? schemaVersion : ResultSchema::currentVersion();
    if (!ResultSchema::migrate(db, url.engine, target, &self->schemaVersion_, &why))
        return fail(why);
    return self;
}

bool ResultDatabase::configure(QString* error)
{
    if (url_.engine != ResultUrl::Engine::Sqlite)
        return exec(QStringLiteral("SET TIME ZONE 'UTC'"), error);
    // WAL is kept in the file, so only the first opener switches it. Switching needs the file to
    // itself and SQLite answers "locked" at once, without its busy handler, while another station
    // opens the same new file: wait for the other as a write would.
    QSqlQuery mode(db_);
    QElapsedTimer waited;
    waited.start();
    for (;;) {
        if (mode.exec(QStringLiteral("PRAGMA journal_mode")) && mode.next() &&
            mode.value(0).toString().compare(QLatin1String("wal"), Qt::CaseInsensitive) == 0)
            break;
        if (mode.exec(QStringLiteral("PRAGMA journal_mode=WAL")) && mode.next())
            break;
        if (mode.lastError().nativeErrorCode() != QLatin1String("5") ||
            waited.elapsed() > kBusyTimeoutMs) {
            if (error)
                *error = mode.lastError().text();
            return false;
        }
        QThread::msleep(20);
    }
    if (mode.value(0).toString().compare(QLatin1String("wal"), Qt::CaseInsensitive) != 0)
        qCWarning(lcModel) << "results database" << url_.path << "cannot use WAL here; journal mode"
                           << mode.value(0).toString();
    return exec(QStringLiteral("PRAGMA synchronous=FULL"), error) &&
           exec(QStringLiteral("PRAGMA foreign_keys=ON"), error) &&
           exec(QStringLiteral("PRAGMA busy_timeout=%1").arg(kBusyTimeoutMs), error);
}

bool ResultDatabase::begin(QString* error)
{
    return exec(url_.engine == ResultUrl::Engine::Sqlite ? QStringLiteral("BEGIN IMMEDIATE")
                                                         : QStringLiteral("BEGIN"),
                error);
}

bool ResultDatabase::commit(QString* error)
{
    return exec(QStringLiteral("COMMIT"), error);
}

void ResultDatabase::rollback()
{
    QSqlQuery(db_).exec(QStringLiteral("ROLLBACK"));
}

bool ResultDatabase::exec(const QString& sql, QString* error)
{
    QSqlQuery query(db_);
    if (query.exec(sql))
        return true;
    if (error)
        *error = query.lastError().text();
    return false;
}

QString ResultDatabase::nowSecondsSql() const
{
    return url_.engine == ResultUrl::Engine::Sqlite
               ? QStringLiteral("((julianday('now') - 2440587.5) * 86400.0)")
               : QStringLiteral("EXTRACT(EPOCH FROM clock_timestamp())");
}

QString ResultDatabase::integrityCheck()
{
    if (url_.engine != ResultUrl::Engine::Sqlite)
        return QString();
    QSqlQuery query(db_);
    if (!query.exec(QStringLiteral("PRAGMA integrity_check")) || !query.next())
        return query.lastError().text();
    return query.value(0).toString();
}

bool ResultDatabase::run(QSqlQuery& query, QString* error)
{
    if (query.exec())
        return true;
    if (error)
        *error = query.lastError().text();
    return false;
}

} // namespace opentop
