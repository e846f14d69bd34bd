#include "tests/support/PostgresServer.h"

#include "model/eol/ResultUrl.h"

#include <QDir>
#include <QElapsedTimer>
#include <QProcess>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QUrl>
#include <QVersionNumber>
#include <cstdlib>
#include <grp.h>
#include <pwd.h>
#include <unistd.h>

namespace opentop::test {

namespace {

constexpr int kPort = 5432; // only names the socket file in the private socket folder
const char* const kUser = "opentop";

QString newestServerBin()
{
    QDir root(QStringLiteral("/usr/lib/postgresql"));
    QString best;
    QVersionNumber bestVersion;
    for (const QString& v : root.entryList(QDir::Dirs | QDir::NoDotAndDotDot)) {
        const QVersionNumber version = QVersionNumber::fromString(v);
        const QString bin = root.filePath(v + QStringLiteral("/bin"));
        if (QFile::exists(bin + QStringLiteral("/initdb")) && version > bestVersion) {
            best = bin;
            bestVersion = version;
        }
    }
    return best;
}

PostgresServer* instance = nullptr;

} // namespace

bool PostgresServer::skipRequested()
{
    return qEnvironmentVariableIntValue("OPENTOP_TEST_PG_SKIP") == 1;
}

PostgresServer* PostgresServer::shared(QString* error)
{
    static QString startError;
    static bool tried = false;
    if (!tried) {
        tried = true;
        auto* server = new PostgresServer;
        if (server->start(&startError)) {
            instance = server;
            // Stopped when the test program ends (a static's destructor: no Qt needed there).
            static struct Stopper
            {
                ~Stopper() { delete instance; }
            } stopper;
        } else {
            delete server;
        }
    }
    if (!instance && error)
        *error = startError;
    return instance;
}

bool PostgresServer::start(QString* error)
{
    externalUrl_ = qEnvironmentVariable("OPENTOP_TEST_PG_URL");
    if (!externalUrl_.isEmpty())
        return true;
    QElapsedTimer timer;
    timer.start();
    bin_ = qEnvironmentVariable("OPENTOP_TEST_PG_BIN", newestServerBin());
    if (bin_.isEmpty() || !QFile::exists(bin_ + QStringLiteral("/initdb"))) {
        *error = QStringLiteral("no PostgreSQL server programs (initdb) in %1 (Debian: apt-get "
                                "install postgresql; scripts/setup.sh installs it)")
                     .arg(bin_.isEmpty() ? QStringLiteral("/usr/lib/postgresql/*/bin") : bin_);
        return false;
    }
    dir_ = std::make_unique<QTemporaryDir>(QDir::tempPath() + QStringLiteral("/opentop-pg-XXXXXX"));
    if (!dir_->isValid()) {
        *error = QStringLiteral("cannot make a temporary folder: ") + dir_->errorString();
        return false;
    }
    if (::geteuid() == 0) {
        // The server refuses to run as root: run it as the package's user.
        const passwd* pw = ::getpwnam("postgres");
        if (!pw) {
            *error = QStringLiteral("running as root and there is no user \"postgres\" to run "
                                    "the server as (Debian's postgresql package makes it)");
            return false;
        }
        if (::chown(QFile::encodeName(dir_->path()).constData(), pw->pw_uid, pw->pw_gid) != 0) {
            *error = QStringLiteral("cannot give %1 to the user postgres").arg(dir_->path());
            return false;
        }
        runAs_ = QStringLiteral("postgres");
    }
    auto run = [&](const QString& program, const QStringList& args, int timeoutMs) {
        return runTool(program, args, timeoutMs, error);
    };
    const QString data = dir_->filePath(QStringLiteral("data"));
    if (!run(bin_ + QStringLiteral("/initdb"),
             {QStringLiteral("-D"), data, QStringLiteral("-U"), QLatin1String(kUser),
              QStringLiteral("-A"), QStringLiteral("trust"), QStringLiteral("-E"),
              QStringLiteral("UTF8"), QStringLiteral("--no-sync"), QStringLiteral("--no-locale")},
             120000))
        return false;
    if (!startServer(error))
        return false;
    startSeconds_ = timer.elapsed() / 1000.0;
    return true;
}

bool PostgresServer::runTool(const QString& program, const QStringList& args, int timeoutMs,
                             QString* error) const
{
    QProcess p;
    p.setWorkingDirectory(dir_->path());
    p.setProcessChannelMode(QProcess::MergedChannels);
    if (runAs_.isEmpty())
        p.start(program, args);
    else
        p.start(QStringLiteral("runuser"),
                QStringList{QStringLiteral("-u"), runAs_, QStringLiteral("--"), program} + args);
    const bool ok =
        p.waitForFinished(timeoutMs) && p.exitStatus() == QProcess::NormalExit && p.exitCode() == 0;
    if (!ok)
        *error = QStringLiteral("%1 failed (%2): %3")
                     .arg(program, p.errorString(), QString::fromLocal8Bit(p.readAll()));
    return ok;
}

bool PostgresServer::startServer(QString* error)
{
    if (!externalUrl_.isEmpty()) {
        *error = QStringLiteral("an external server (OPENTOP_TEST_PG_URL) is not started here");
        return false;
    }
    // fsync off (nothing outlives the test run), but each commit written before it returns: a
    // server stopped at once (stopServer) keeps what it committed, as a real one does.
    const QString options = QStringLiteral("-k %1 -p %2 -c listen_addresses='' -c fsync=off "
                                           "-c full_page_writes=off")
                                .arg(dir_->path())
                                .arg(kPort);
    if (!runTool(bin_ + QStringLiteral("/pg_ctl"),
                 {QStringLiteral("-D"), dir_->filePath(QStringLiteral("data")),
                  QStringLiteral("-l"), dir_->filePath(QStringLiteral("log")), QStringLiteral("-o"),
                  options, QStringLiteral("-w"), QStringLiteral("-t"), QStringLiteral("60"),
                  QStringLiteral("start")},
                 90000, error)) {
        QFile log(dir_->filePath(QStringLiteral("log")));
        if (log.open(QIODevice::ReadOnly))
            *error += QStringLiteral("\nserver log:\n") + QString::fromLocal8Bit(log.readAll());
        return false;
    }
    running_ = true;
    return true;
}

bool PostgresServer::stopServer(QString* error)
{
    if (!externalUrl_.isEmpty()) {
        *error = QStringLiteral("an external server (OPENTOP_TEST_PG_URL) is not stopped here");
        return false;
    }
    // As a crash or a pulled cable would: immediately, connections broken.
    if (!runTool(bin_ + QStringLiteral("/pg_ctl"),
                 {QStringLiteral("-D"), dir_->filePath(QStringLiteral("data")),
                  QStringLiteral("-m"), QStringLiteral("immediate"), QStringLiteral("-w"),
                  QStringLiteral("stop")},
                 60000, error))
        return false;
    running_ = false;
    return true;
}

PostgresServer::~PostgresServer()
{
    if (!running_)
        return;
    // std::system: this runs when the test program ends, after the QCoreApplication is gone.
    QString command = QStringLiteral("%1/pg_ctl -D %2/data -m immediate -w stop >/dev/null 2>&1")
                          .arg(bin_, dir_->path());
    if (!runAs_.isEmpty())
        command = QStringLiteral("runuser -u %1 -- ").arg(runAs_) + command;
    [[maybe_unused]] const int status = std::system(command.toLocal8Bit().constData());
}

QString PostgresServer::adminUrl() const
{
    if (!externalUrl_.isEmpty())
        return externalUrl_;
    return QStringLiteral("postgresql://%1@/postgres?host=%2&port=%3")
        .arg(QLatin1String(kUser), dir_->path())
        .arg(kPort);
}

QString PostgresServer::createDatabase(const QString& name, QString* error)
{
    const auto admin = ResultUrl::parse(adminUrl(), error);
    if (!admin)
        return QString();
    const QString connection = QStringLiteral("opentop-test-pg-admin");
    QString url;
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QPSQL"), connection);
        db.setHostName(admin->host);
        if (admin->port > 0)
            db.setPort(admin->port);
        db.setUserName(admin->user);
        db.setPassword(admin->password);
        db.setDatabaseName(admin->database);
        db.setConnectOptions(admin->options);
        if (!db.open()) {
            *error = QStringLiteral("cannot connect to the test server %1: %2")
                         .arg(admin->displayText(), db.lastError().text());
        } else {
            QSqlQuery q(db);
            if (!externalUrl_.isEmpty()) // a rerun on a kept server starts from nothing
                q.exec(QStringLiteral("DROP DATABASE IF EXISTS %1").arg(name));
            if (!q.exec(QStringLiteral("CREATE DATABASE %1").arg(name))) {
                *error = q.lastError().text();
            } else {
                // Every part explicit (the environment may name another database).
                auto enc = [](const QString& part) {
                    return QString::fromLatin1(QUrl::toPercentEncoding(part));
                };
                url = QStringLiteral("postgresql://%1:%2@/%3?host=%4")
                          .arg(enc(admin->user), enc(admin->password), name, enc(admin->host));
                if (admin->port > 0)
                    url += QStringLiteral("&port=%1").arg(admin->port);
                for (const QString& option :
                     admin->options.split(QLatin1Char(';'), Qt::SkipEmptyParts))
                    url += QLatin1Char('&') + option;
            }
            db.close();
        }
    }
    QSqlDatabase::removeDatabase(connection);
    return url;
}

} // namespace opentop::test
