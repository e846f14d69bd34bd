#pragma once

#include "model/eol/UnitRecord.h"

#include <QCoreApplication>
#include <QSqlDatabase>
#include <memory>
#include <optional>

namespace opentop {

// The station's own store for results the results database could not take (a server down, the
// network gone): a SQLite file on the station's disk, one per results database, that keeps each
// begun or finished unit until the database has it (docs/eol-results.md, "A server that goes
// away"). Entries leave in the order they came, and only once the database committed them; a
// station killed in between sends one again, which the database recognises by the unit's id
// (ResultStore), so each reaches it exactly once.
//
// Crash-safe: every append is its own committed transaction with synchronous=FULL before it
// returns. Several processes of one PC may share a spool (SQLite's locking); each delivers from
// the oldest entry.
class ResultSpool
{
    Q_DECLARE_TR_FUNCTIONS(opentop::ResultSpool)
public:
    enum class Kind
    {
        Begin, // the unit's 'running' row
        Finish // the whole record with its verdict
    };
    struct Entry
    {
        qint64 seq = 0;
        Kind kind = Kind::Begin;
        UnitRecord record;
        QString lease; // the process that tested the unit (ResultStore's leases)
    };

    ~ResultSpool();
    ResultSpool(const ResultSpool&) = delete;
    ResultSpool& operator=(const ResultSpool&) = delete;

    // The spool file for results database `databaseUrl` in `folder`, made when missing; null
    // with *error naming the file when it cannot be opened.
    static std::unique_ptr<ResultSpool> open(const QString& folder, const QString& databaseUrl,
                                             QString* error);
    // Where the spool files live: opentop/spool in the user's data folder (beside the default
    // results file).
    static QString defaultFolder();

    QString path() const { return m_path; }
    bool append(Kind kind, const UnitRecord& record, const QString& lease, QString* error);
    // The oldest entry; none when the spool is empty or on an error (*error set).
    std::optional<Entry> oldest(QString* error);
    bool remove(qint64 seq, QString* error);
    // Entries waiting; -1 on an error.
    int count(QString* error = nullptr);

private:
    ResultSpool() = default;

    QString m_path;
    QString m_connection;
    QSqlDatabase m_db;
};

} // namespace opentop
