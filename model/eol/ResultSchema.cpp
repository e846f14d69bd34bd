#include "model/eol/ResultSchema.h"

#include "model/ModelLog.h"
#include "model/eol/UnitRecordJson.h"

#include <QSqlError>
#include <QSqlQuery>

namespace opentop {

namespace {

// Any constant: the advisory lock the stations of one PostgreSQL database migrate under.
constexpr qint64 kMigrationLock = 0x4f54454f4c; // "OTEOL"

bool exec(QSqlDatabase& db, const QString& sql, QString* error)
{
    QSqlQuery query(db);
    if (query.exec(sql))
        return true;
    if (error)
        *error = query.lastError().text() + QStringLiteral(" [") + sql.simplified().left(120) +
                 QLatin1Char(']');
    return false;
}

} // namespace

const QVector<ResultSchema::Migration>& ResultSchema::migrations()
{
    static const QVector<Migration> list{
        {1,
         QStringLiteral("units, drives, written values, measurements"),
         {QStringLiteral("CREATE TABLE units ("
                         " unit_id VARCHAR(40) NOT NULL PRIMARY KEY,"
                         " serial VARCHAR(200) NOT NULL,"
                         " station VARCHAR(200) NOT NULL,"
                         " operator_name VARCHAR(200) NOT NULL,"
                         " started_utc VARCHAR(32) NOT NULL,"
                         " ended_utc VARCHAR(32),"
                         " recipe_name VARCHAR(200) NOT NULL,"
                         " recipe_revision VARCHAR(100) NOT NULL,"
                         " recipe_checksum VARCHAR(200) NOT NULL,"
                         " status VARCHAR(20) NOT NULL CHECK (status IN"
                         "  ('running', 'interrupted', 'pass', 'fail', 'aborted')),"
                         " failure_reason TEXT NOT NULL)"),
          QStringLiteral("CREATE TABLE unit_drives ("
                         " unit_id VARCHAR(40) NOT NULL REFERENCES units (unit_id),"
                         " drive_index INTEGER NOT NULL,"
                         " machine_number INTEGER NOT NULL,"
                         " model VARCHAR(100) NOT NULL,"
                         " variant VARCHAR(100) NOT NULL,"
                         " firmware VARCHAR(100) NOT NULL,"
                         " PRIMARY KEY (unit_id, drive_index))"),
          QStringLiteral("CREATE TABLE written_values ("
                         " unit_id VARCHAR(40) NOT NULL REFERENCES units (unit_id),"
                         " seq INTEGER NOT NULL,"
                         " machine_number INTEGER NOT NULL,"
                         " parameter VARCHAR(200) NOT NULL,"
                         " label VARCHAR(400) NOT NULL,"
                         " value_text TEXT NOT NULL,"
                         " was_written INTEGER NOT NULL,"
                         " verified INTEGER NOT NULL,"
                         " read_back TEXT NOT NULL,"
                         " PRIMARY KEY (unit_id, seq))"),
          QStringLiteral("CREATE TABLE measurements ("
                         " unit_id VARCHAR(40) NOT NULL REFERENCES units (unit_id),"
                         " seq INTEGER NOT NULL,"
                         " machine_number INTEGER NOT NULL,"
                         " step VARCHAR(400) NOT NULL,"
                         " quantity VARCHAR(200) NOT NULL,"
                         " measured DOUBLE PRECISION NOT NULL,"
                         " unit VARCHAR(40) NOT NULL,"
                         " lower_limit DOUBLE PRECISION,"
                         " upper_limit DOUBLE PRECISION,"
                         " passed INTEGER NOT NULL,"
                         " PRIMARY KEY (unit_id, seq))"),
          QStringLiteral("CREATE INDEX units_by_serial ON units (serial, started_utc)"),
          QStringLiteral("CREATE INDEX units_by_time ON units (started_utc)")},
         {}},
        {2,
         QStringLiteral("traffic around a failure; indexes by recipe and by station"),
         {QStringLiteral("CREATE TABLE unit_traffic ("
                         " unit_id VARCHAR(40) NOT NULL REFERENCES units (unit_id),"
                         " seq INTEGER NOT NULL,"
                         " line TEXT NOT NULL,"
                         " PRIMARY KEY (unit_id, seq))"),
          QStringLiteral("CREATE INDEX units_by_recipe ON units (recipe_name, started_utc)"),
          QStringLiteral("CREATE INDEX units_by_station ON units (station, status)")},
         {}},
        {3,
         QStringLiteral("station leases: which running unit belongs to a process still alive"),
         {QStringLiteral("CREATE TABLE station_leases ("
                         " lease_id VARCHAR(40) NOT NULL PRIMARY KEY,"
                         " station VARCHAR(200) NOT NULL,"
                         " host VARCHAR(200) NOT NULL,"
                         " pid BIGINT NOT NULL,"
                         " program VARCHAR(100) NOT NULL,"
                         " started_utc VARCHAR(32) NOT NULL,"
                         " heartbeat_s DOUBLE PRECISION NOT NULL)"),
          // NULL on rows from before leases: the station name decides for those, as it did.
          QStringLiteral("ALTER TABLE units ADD COLUMN lease_id VARCHAR(40)"),
          QStringLiteral("CREATE INDEX units_by_status ON units (status)")},
         {}},
        {4,
         QStringLiteral("how each drive's variant was known: read, probed, confirmed, assumed"),
         // NULL on rows from before: nothing was said of the variant's proof then.
         {QStringLiteral("ALTER TABLE unit_drives ADD COLUMN variant_source VARCHAR(20)"),
          QStringLiteral("ALTER TABLE unit_drives ADD COLUMN variant_proof TEXT")},
         {}},
        {5,
         QStringLiteral("station errors kept apart from verdicts; attempt numbers"),
         {// PostgreSQL names a column's CHECK <table>_<column>_check.
          QStringLiteral("ALTER TABLE units DROP CONSTRAINT units_status_check"),
          QStringLiteral("ALTER TABLE units ADD CONSTRAINT units_status_check CHECK (status IN"
                         " ('running', 'interrupted', 'pass', 'fail', 'aborted', 'error'))"),
          QStringLiteral("ALTER TABLE units ADD COLUMN attempt INTEGER"),
          QStringLiteral("CREATE INDEX units_by_checksum ON units (recipe_checksum, serial)")},
         {QStringLiteral("CREATE TABLE units_v5 ("
                         " unit_id VARCHAR(40) NOT NULL PRIMARY KEY,"
                         " serial VARCHAR(200) NOT NULL,"
                         " station VARCHAR(200) NOT NULL,"
                         " operator_name VARCHAR(200) NOT NULL,"
                         " started_utc VARCHAR(32) NOT NULL,"
                         " ended_utc VARCHAR(32),"
                         " recipe_name VARCHAR(200) NOT NULL,"
                         " recipe_revision VARCHAR(100) NOT NULL,"
                         " recipe_checksum VARCHAR(200) NOT NULL,"
                         " status VARCHAR(20) NOT NULL CHECK (status IN"
                         "  ('running', 'interrupted', 'pass', 'fail', 'aborted', 'error')),"
                         " failure_reason TEXT NOT NULL,"
                         " lease_id VARCHAR(40),"
                         " attempt INTEGER)"),
          QStringLiteral("INSERT INTO units_v5 SELECT unit_id, serial, station, operator_name,"
                         " started_utc, ended_utc, recipe_name, recipe_revision, recipe_checksum,"
                         " status, failure_reason, lease_id, NULL FROM units"),
          QStringLiteral("DROP TABLE units"),
          QStringLiteral("ALTER TABLE units_v5 RENAME TO units"),
          QStringLiteral("CREATE INDEX units_by_serial ON units (serial, started_utc)"),
          QStringLiteral("CREATE INDEX units_by_time ON units (started_utc)"),
          QStringLiteral("CREATE INDEX units_by_recipe ON units (recipe_name, started_utc)"),
          QStringLiteral("CREATE INDEX units_by_station ON units (station, status)"),
          QStringLiteral("CREATE INDEX units_by_status ON units (status)"),
          QStringLiteral("CREATE INDEX units_by_checksum ON units (recipe_checksum, serial)")}},
        {6,
         QStringLiteral("users, recipe approvals, audit trail; each unit names its approval"),
         {QStringLiteral("CREATE TABLE users ("
                         " user_name VARCHAR(100) NOT NULL PRIMARY KEY,"
                         " display_name VARCHAR(200) NOT NULL,"
                         " role VARCHAR(20) NOT NULL CHECK (role IN"
                         "  ('operator', 'technician', 'engineer', 'administrator')),"
                         " password_hash VARCHAR(200) NOT NULL,"
                         " salt VARCHAR(100) NOT NULL,"
                         " iterations INTEGER NOT NULL,"
                         " active INTEGER NOT NULL,"
                         " created_utc VARCHAR(32) NOT NULL)"),
          QStringLiteral("CREATE TABLE recipe_approvals ("
                         " approval_id VARCHAR(40) NOT NULL PRIMARY KEY,"
                         " recipe_checksum VARCHAR(200) NOT NULL,"
                         " recipe_name VARCHAR(200) NOT NULL,"
                         " recipe_revision VARCHAR(100) NOT NULL,"
                         " approver VARCHAR(100) NOT NULL REFERENCES users (user_name),"
                         " approved_utc VARCHAR(32) NOT NULL,"
                         " station VARCHAR(200) NOT NULL,"
                         " superseded INTEGER NOT NULL)"),
          QStringLiteral(
              "CREATE INDEX approvals_by_checksum ON recipe_approvals (recipe_checksum)"),
          // at_s: seconds since 1970 by the database's clock, one order for every station.
          QStringLiteral("CREATE TABLE audit ("
                         " audit_id VARCHAR(40) NOT NULL PRIMARY KEY,"
                         " at_s DOUBLE PRECISION NOT NULL,"
                         " station VARCHAR(200) NOT NULL,"
                         " user_name VARCHAR(100) NOT NULL,"
                         " action VARCHAR(40) NOT NULL,"
                         " detail TEXT NOT NULL)"),
          QStringLiteral("CREATE INDEX audit_by_time ON audit (at_s)"),
          // NULL on units tested before users (or on an unmanaged station).
          QStringLiteral("ALTER TABLE units ADD COLUMN approval_id VARCHAR(40)"),
          QStringLiteral("ALTER TABLE units ADD COLUMN approver VARCHAR(100)")},
         {}},
    };
    return list;
}

int ResultSchema::currentVersion()
{
    return migrations().constLast().version;
}

int ResultSchema::version(QSqlDatabase& db, QString* error)
{
    if (!db.tables().contains(QStringLiteral("schema_version")))
        return 0;
    QSqlQuery query(db);
    if (!query.exec(QStringLiteral("SELECT MAX(version) FROM schema_version")) || !query.next()) {
        if (error)
            *error = query.lastError().text();
        return -1;
    }
    return query.value(0).toInt();
}

bool ResultSchema::migrate(QSqlDatabase& db, ResultUrl::Engine engine, int target,
                           int* appliedVersion, QString* error)
{
    const bool sqlite = engine == ResultUrl::Engine::Sqlite;
    // A table rebuilt (sqliteStatements) is dropped with its children's rows still pointing at
    // it: SQLite checks foreign keys only outside a transaction, so they are checked by hand
    // before the commit and switched on again after it.
    if (sqlite && !exec(db, QStringLiteral("PRAGMA foreign_keys=OFF"), error))
        return false;
    auto keysOn = [&] {
        if (sqlite)
            QSqlQuery(db).exec(QStringLiteral("PRAGMA foreign_keys=ON"));
    };
    if (!exec(db, sqlite ? QStringLiteral("BEGIN IMMEDIATE") : QStringLiteral("BEGIN"), error)) {
        keysOn();
        return false;
    }
    auto rollback = [&] {
        QSqlQuery(db).exec(QStringLiteral("ROLLBACK"));
        keysOn();
        return false;
    };
    if (!sqlite &&
        !exec(db, QStringLiteral("SELECT pg_advisory_xact_lock(%1)").arg(kMigrationLock), error))
        return rollback();
    // Under the lock: no other station creates it meanwhile.
    if (!db.tables().contains(QStringLiteral("schema_version")) &&
        !exec(db,
              QStringLiteral("CREATE TABLE schema_version ("
                             " version INTEGER NOT NULL PRIMARY KEY,"
                             " applied_utc VARCHAR(32) NOT NULL,"
                             " description VARCHAR(400) NOT NULL)"),
              error))
        return rollback();
    const int found = version(db, error);
    if (found < 0)
        return rollback();
    if (found > currentVersion()) {
        if (error)
            *error = tr("the results database has schema version %1, newer than this program "
                        "knows (%2): update OpenTOP on this station; nothing was written")
                         .arg(found)
                         .arg(currentVersion());
        return rollback();
    }
    int now = found;
    for (const Migration& m : migrations()) {
        if (m.version <= found || m.version > target)
            continue;
        const QStringList& statements =
            sqlite && !m.sqliteStatements.isEmpty() ? m.sqliteStatements : m.statements;
        for (const QString& sql : statements)
            if (!exec(db, sql, error))
                return rollback();
        QSqlQuery insert(db);
        insert.prepare(QStringLiteral(
            "INSERT INTO schema_version (version, applied_utc, description) VALUES (?, ?, ?)"));
        insert.addBindValue(m.version);
        insert.addBindValue(UnitRecordJson::timeText(QDateTime::currentDateTimeUtc()));
        insert.addBindValue(m.description);
        if (!insert.exec()) {
            if (error)
                *error = insert.lastError().text();
            return rollback();
        }
        qCInfo(lcModel) << "results database: schema version" << m.version << m.description;
        now = m.version;
    }
    if (sqlite) {
        QSqlQuery check(db);
        if (!check.exec(QStringLiteral("PRAGMA foreign_key_check")) || check.next()) {
            if (error)
                *error = check.lastError().isValid()
                             ? check.lastError().text()
                             : tr("the migration left a record pointing at no unit (table %1)")
                                   .arg(check.value(0).toString());
            return rollback();
        }
    }
    if (!exec(db, QStringLiteral("COMMIT"), error))
        return rollback();
    keysOn();
    if (appliedVersion)
        *appliedVersion = now;
    return true;
}

} // namespace opentop
