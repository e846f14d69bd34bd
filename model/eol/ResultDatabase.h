#pragma once

#include "model/eol/ResultUrl.h"

#include <QCoreApplication>
#include <QSqlDatabase>
#include <memory>

class QSqlQuery;

namespace opentop {

// An open connection to the results database (docs/eol-results.md), at the program's schema
// version. Each instance has its own QSqlDatabase connection name and must be used only on the
// thread that opened it; a second thread or station opens its own.
//
// SQLite: WAL (readers never block the writer, a killed writer leaves the file valid),
// synchronous=FULL (a committed unit survives a power cut: in WAL mode NORMAL may lose the last
// commits, and a unit that was labelled PASS must have its record; one fsync per unit costs
// nothing at a unit a minute), foreign keys on, and a busy timeout so that a second writer
// waits instead of failing.
class ResultDatabase
{
    Q_DECLARE_TR_FUNCTIONS(opentop::ResultDatabase)
public:
    static constexpr int kBusyTimeoutMs = 10000;

    ~ResultDatabase();
    ResultDatabase(const ResultDatabase&) = delete;
    ResultDatabase& operator=(const ResultDatabase&) = delete;

    // Opens, configures and migrates to `schemaVersion` (tests give an older one); null with
    // *error naming the database (never its password) and why.
    static std::unique_ptr<ResultDatabase> open(const QString& url, QString* error,
                                                int schemaVersion = -1);
    static std::unique_ptr<ResultDatabase> open(const ResultUrl& url, QString* error,
                                                int schemaVersion = -1);

    const ResultUrl& url() const { return url_; }
    ResultUrl::Engine engine() const { return url_.engine; }
    QSqlDatabase& db() { return db_; }
    QString connectionName() const { return connectionName_; }
    int schemaVersion() const { return schemaVersion_; }

    // A write transaction (SQLite: BEGIN IMMEDIATE, so the write lock is taken at once and a
    // busy database is waited for); rollback() is harmless when nothing is open.
    bool begin(QString* error);
    bool commit(QString* error);
    void rollback();
    // Runs one statement (pragmas, tests); *error gets the driver's message.
    bool exec(const QString& sql, QString* error);
    // Runs a prepared query; false with the driver's message in *error.
    static bool run(QSqlQuery& query, QString* error);
    // An SQL expression for the database's own clock in seconds since 1970 (leases compare
    // heartbeats by one clock, not by the clocks of the stations that wrote them).
    QString nowSecondsSql() const;
    // SQLite's PRAGMA integrity_check result ("ok"), empty on PostgreSQL.
    QString integrityCheck();

private:
    ResultDatabase() = default;
    bool configure(QString* error);

    ResultUrl url_;
    QString connectionName_;
    QSqlDatabase db_;
    int schemaVersion_ = 0;
};

} // namespace opentop
