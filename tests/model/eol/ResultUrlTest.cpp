#include "model/eol/ResultUrl.h"

#include <gtest/gtest.h>

using namespace opentop;

namespace {

QProcessEnvironment noPg()
{
    return QProcessEnvironment();
}

} // namespace

TEST(ResultUrlTest, FilePathAndSqliteFormAreSqlite)
{
    QString error;
    auto url = ResultUrl::parse(QStringLiteral("/var/lib/opentop/results.db"), &error, noPg());
    ASSERT_TRUE(url);
    EXPECT_EQ(url->engine, ResultUrl::Engine::Sqlite);
    EXPECT_EQ(url->path, QStringLiteral("/var/lib/opentop/results.db"));
    EXPECT_EQ(url->driverName(), QStringLiteral("QSQLITE"));
    url = ResultUrl::parse(QStringLiteral("sqlite:results.db"), &error, noPg());
    ASSERT_TRUE(url);
    EXPECT_EQ(url->path, QStringLiteral("results.db"));
    EXPECT_EQ(url->displayText(), QStringLiteral("sqlite:results.db"));
    EXPECT_FALSE(ResultUrl::parse(QStringLiteral("sqlite:"), &error, noPg()));
    EXPECT_FALSE(ResultUrl::parse(QStringLiteral("mysql://h/db"), &error, noPg()));
    EXPECT_TRUE(error.contains(QLatin1String("postgresql://"))) << error.toStdString();
    EXPECT_FALSE(ResultUrl::parse(QString(), &error, noPg()));
}

TEST(ResultUrlTest, PostgresUrlHasEveryPartAndNeverShowsThePassword)
{
    QString error;
    const auto url = ResultUrl::parse(
        QStringLiteral("postgresql://eol:s%40cret@db.factory:6543/results?sslmode=require"), &error,
        noPg());
    ASSERT_TRUE(url) << error.toStdString();
    EXPECT_EQ(url->engine, ResultUrl::Engine::Postgres);
    EXPECT_EQ(url->user, QStringLiteral("eol"));
    EXPECT_EQ(url->password, QStringLiteral("s@cret"));
    EXPECT_EQ(url->host, QStringLiteral("db.factory"));
    EXPECT_EQ(url->port, 6543);
    EXPECT_EQ(url->database, QStringLiteral("results"));
    // A server out of reach is given up after 5 s unless the URL says otherwise.
    EXPECT_EQ(url->options, QStringLiteral("sslmode=require;connect_timeout=5"));
    const auto patient = ResultUrl::parse(
        QStringLiteral("postgresql://db.factory/results?connect_timeout=30"), &error, noPg());
    ASSERT_TRUE(patient) << error.toStdString();
    EXPECT_EQ(patient->options, QStringLiteral("connect_timeout=30"));
    EXPECT_EQ(url->driverName(), QStringLiteral("QPSQL"));
    EXPECT_FALSE(url->displayText().contains(QLatin1String("s@cret")));
    EXPECT_EQ(url->displayText(), QStringLiteral("postgresql://eol@db.factory:6543/results"));
}

TEST(ResultUrlTest, SocketDirectoryAndIpv6)
{
    QString error;
    auto url = ResultUrl::parse(
        QStringLiteral("postgres://eol@/results?host=/run/postgresql&port=5433"), &error, noPg());
    ASSERT_TRUE(url) << error.toStdString();
    EXPECT_EQ(url->host, QStringLiteral("/run/postgresql"));
    EXPECT_EQ(url->port, 5433);
    EXPECT_EQ(url->displayText(),
              QStringLiteral("postgresql://eol@:5433/results?host=/run/postgresql"));
    url = ResultUrl::parse(QStringLiteral("postgresql://eol@%2Ftmp%2Fpg/results"), &error, noPg());
    ASSERT_TRUE(url);
    EXPECT_EQ(url->host, QStringLiteral("/tmp/pg"));
    url = ResultUrl::parse(QStringLiteral("postgresql://[::1]:5432/r"), &error, noPg());
    ASSERT_TRUE(url);
    EXPECT_EQ(url->host, QStringLiteral("::1"));
    EXPECT_EQ(url->port, 5432);
}

TEST(ResultUrlTest, MissingPartsComeFromTheLibpqEnvironment)
{
    QProcessEnvironment env;
    env.insert(QStringLiteral("PGHOST"), QStringLiteral("pg.local"));
    env.insert(QStringLiteral("PGPORT"), QStringLiteral("5499"));
    env.insert(QStringLiteral("PGUSER"), QStringLiteral("station"));
    env.insert(QStringLiteral("PGPASSWORD"), QStringLiteral("pw"));
    env.insert(QStringLiteral("PGDATABASE"), QStringLiteral("eol"));
    QString error;
    auto url = ResultUrl::parse(QStringLiteral("postgresql://"), &error, env);
    ASSERT_TRUE(url) << error.toStdString();
    EXPECT_EQ(url->host, QStringLiteral("pg.local"));
    EXPECT_EQ(url->port, 5499);
    EXPECT_EQ(url->user, QStringLiteral("station"));
    EXPECT_EQ(url->password, QStringLiteral("pw"));
    EXPECT_EQ(url->database, QStringLiteral("eol"));
    url = ResultUrl::parse(QStringLiteral("postgresql://other@db/results"), &error, env);
    ASSERT_TRUE(url);
    EXPECT_EQ(url->user, QStringLiteral("other")); // the URL's parts win
    EXPECT_EQ(url->host, QStringLiteral("db"));
    EXPECT_EQ(url->database, QStringLiteral("results"));
    EXPECT_EQ(url->port, 5499);
}

TEST(ResultUrlTest, RefusesABadPortAndAnUnknownOption)
{
    QString error;
    EXPECT_FALSE(ResultUrl::parse(QStringLiteral("postgresql://h:99999/db"), &error, noPg()));
    EXPECT_TRUE(error.contains(QLatin1String("99999")));
    EXPECT_FALSE(
        ResultUrl::parse(QStringLiteral("postgresql://h/db?sslmod=require"), &error, noPg()));
    EXPECT_TRUE(error.contains(QLatin1String("sslmod")));
}
