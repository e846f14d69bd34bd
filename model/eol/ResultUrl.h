#pragma once

#include <QCoreApplication>
#include <QProcessEnvironment>
#include <QString>
#include <optional>

namespace opentop {

// Where the results database is (docs/eol-results.md): a file path or sqlite:PATH (SQLite), or
// postgresql://[user[:password]@][host][:port][/database][?host=/socket/dir&sslmode=...]
// (PostgreSQL; postgres:// too). Parts a PostgreSQL URL leaves out come from PGHOST, PGPORT,
// PGUSER, PGPASSWORD and PGDATABASE, as libpq takes them.
struct ResultUrl
{
    Q_DECLARE_TR_FUNCTIONS(opentop::ResultUrl)
public:
    enum class Engine
    {
        Sqlite,
        Postgres
    };
    Engine engine = Engine::Sqlite;
    QString path; // SQLite: the file
    QString host; // PostgreSQL: a name, an address, or a socket directory (starts with /)
    int port = -1;
    QString user;
    QString password;
    QString database;
    QString options; // libpq keywords QPSQL passes on: "sslmode=require;connect_timeout=5"

    // Where a station keeps its results when it is not told: results.db in the user's data
    // folder ($XDG_DATA_HOME/opentop, ~/.local/share/opentop).
    static QString defaultLocation();
    // Where a station's results go: `url`, else OPENTOP_EOL_DB, else the default file (its
    // folder made).
    static QString stationLocation(const QString& url);
    static std::optional<ResultUrl>
    parse(const QString& text, QString* error,
          const QProcessEnvironment& environment = QProcessEnvironment::systemEnvironment());
    // The URL to show: never the password.
    QString displayText() const;
    QString driverName() const; // "QSQLITE", "QPSQL"
};

} // namespace opentop
