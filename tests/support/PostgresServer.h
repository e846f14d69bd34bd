#pragma once

#include <QString>
#include <QTemporaryDir>
#include <memory>

namespace opentop::test {

// A real PostgreSQL server for the results-database tests, started by the tests themselves:
// a throw-away cluster (initdb + pg_ctl of Debian's postgresql package) in a temporary folder,
// listening only on a Unix socket in that folder, with fsync off (commits still written before
// they return, so a server stopped at once keeps them); stopped when the tests end.
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
    // Stops the server at once (pg_ctl -m immediate: connections break as in a crash) and
    // starts it again on the same data; false with *error (also for an external server).
    bool stopServer(QString* error);
    bool startServer(QString* error);

private:
    PostgresServer() = default;
    bool start(QString* error);
    QString adminUrl() const;
    bool runTool(const QString& program, const QStringList& args, int timeoutMs,
                 QString* error) const;

    std::unique_ptr<QTemporaryDir> dir_;
    QString bin_;
    QString runAs_; // "postgres" when started as root
    QString externalUrl_;
    double startSeconds_ = 0;
    bool running_ = false;
};

} // namespace opentop::test
