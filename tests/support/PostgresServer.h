#pragma once

#include <QString>
#include <QTemporaryDir>
#include <memory>

namespace opentop::test {

// A real PostgreSQL server for the results-database tests, started by the tests themselves:
// a throw-away cluster (initdb + pg_ctl of Debian's postgresql package) in a temporary folder,
// listening only on a Unix socket in that folder, with fsync off; stopped when the tests end.
// As root the server runs as the user "postgres" (runuser), as anyone else as that user.
//
// OPENTOP_TEST_PG_URL=postgresql://...  use that server instead (a user that may CREATE DATABASE)
// OPENTOP_TEST_PG_BIN=DIR                the server programs' folder (default: the newest
//                                       /usr/lib/postgresql/*/bin)
// OPENTOP_TEST_PG_SKIP=1                skip the PostgreSQL tests; without it a server that
//                                       cannot be started is a failure, with the reason.
class PostgresServer
{
public:
    // The one server of this test run, started on first use; null with *error when it cannot
    // be started.
    static PostgresServer* shared(QString* error);
    static bool skipRequested();

    ~PostgresServer();
    // A new, empty database on the server; its URL (postgresql://...).
    QString createDatabase(const QString& name, QString* error);
    double startSeconds() const { return startSeconds_; }

private:
    PostgresServer() = default;
    bool start(QString* error);
    QString adminUrl() const;

    std::unique_ptr<QTemporaryDir> dir_;
    QString bin_;
    QString runAs_; // "postgres" when started as root
    QString externalUrl_;
    double startSeconds_ = 0;
    bool running_ = false;
};

} // namespace opentop::test
