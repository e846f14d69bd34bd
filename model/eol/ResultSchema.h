#pragma once

#include "model/eol/ResultUrl.h"

#include <QCoreApplication>
#include <QSqlDatabase>
#include <QStringList>
#include <QVector>

namespace opentop {

// The results database's tables (docs/eol-results.md), the same on SQLite and PostgreSQL:
// portable types only (INTEGER, VARCHAR, TEXT, DOUBLE PRECISION; times as ISO 8601 UTC text,
// which sorts as time; booleans as 0/1; a unit's key is a UUID the station makes, so no engine's
// auto-increment is needed). Versions are applied in order, each in the same transaction as its
// row in schema_version, so a database is always at exactly one version.
class ResultSchema
{
    Q_DECLARE_TR_FUNCTIONS(opentop::ResultSchema)
public:
    struct Migration
    {
        int version;
        QString description;
        QStringList statements;
        // SQLite cannot change a CHECK constraint in place: when given, these replace
        // `statements` there (a table rebuilt under the migration's transaction).
        QStringList sqliteStatements;
    };
    static const QVector<Migration>& migrations();
    static int currentVersion(); // the newest this program knows

    // Brings the database to `target` (default: current), refusing one that is newer than this
    // program. Safe when several stations do it at once (SQLite: BEGIN IMMEDIATE; PostgreSQL: a
    // transaction-scoped advisory lock). *appliedVersion is the version afterwards.
    static bool migrate(QSqlDatabase& db, ResultUrl::Engine engine, int target, int* appliedVersion,
                        QString* error);
    static int version(QSqlDatabase& db, QString* error); // 0: no schema yet, -1: error
};

} // namespace opentop
