// The results database on a real PostgreSQL server (PostgresServer starts a throw-away one):
// the same schema and the same records as SQLite, and two station processes writing at once.
#include "model/eol/ResultDatabase.h"
#include "model/eol/ResultQueries.h"
#include "model/eol/ResultSchema.h"
#include "model/eol/ResultStore.h"
#include "model/eol/UnitRecordJson.h"
#include "tests/support/EolSampleUnit.h"
#include "tests/support/PostgresServer.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

class ResultPostgresTest : public ::testing::Test
{
protected:
    void SetUp() override
    {
        if (test::PostgresServer::skipRequested())
            GTEST_SKIP() << "OPENTOP_TEST_PG_SKIP=1: PostgreSQL tests skipped on request";
        QString error;
        QElapsedTimer timer;
        timer.start();
        server = test::PostgresServer::shared(&error);
        ASSERT_TRUE(server) << "cannot start a PostgreSQL server for the tests: "
                            << error.toStdString();
        const QString name = QStringLiteral("eol_%1").arg(
            QString::fromLatin1(::testing::UnitTest::GetInstance()->current_test_info()->name())
                .toLower());
        url = server->createDatabase(name, &error);
        ASSERT_FALSE(url.isEmpty()) << error.toStdString();
        std::printf("PostgreSQL ready in %.1f s (server start %.1f s)\n", timer.elapsed() / 1000.0,
                    server->startSeconds());
    }
    std::unique_ptr<ResultDatabase> open(int version = -1)
    {
        QString error;
        auto db = ResultDatabase::open(url, &error, version);
        EXPECT_TRUE(db) << error.toStdString();
        return db;
    }

    test::PostgresServer* server = nullptr;
    QString url;
};

} // namespace

TEST_F(ResultPostgresTest, SameRecordReadsBackIdenticallyFromSqliteAndPostgres)
{
    auto pg = open();
    ASSERT_TRUE(pg);
    EXPECT_EQ(pg->engine(), ResultUrl::Engine::Postgres);
    EXPECT_EQ(pg->schemaVersion(), ResultSchema::currentVersion());
    QTemporaryDir dir;
    QString error;
    auto lite = ResultDatabase::open(dir.filePath(QStringLiteral("same.db")), &error);
    ASSERT_TRUE(lite) << error.toStdString();
    for (UnitStatus status : {UnitStatus::Pass, UnitStatus::Fail}) {
        UnitRecord r = test::eolSampleUnit(QStringLiteral("SN-BOTH"), status);
        r.id = QStringLiteral("same-id-%1").arg(unitStatusName(status));
        UnitRecord forPg = r;
        ResultStore pgStore(*pg);
        ResultStore liteStore(*lite);
        ASSERT_TRUE(pgStore.beginUnit(forPg, &error) && pgStore.finishUnit(forPg, &error))
            << error.toStdString();
        ASSERT_TRUE(liteStore.beginUnit(r, &error) && liteStore.finishUnit(r, &error))
            << error.toStdString();
        const auto fromPg = ResultQueries(*pg).load(r.id, &error);
        const auto fromLite = ResultQueries(*lite).load(r.id, &error);
        ASSERT_TRUE(fromPg && fromLite) << error.toStdString();
        EXPECT_EQ(UnitRecordJson::toBytes(*fromPg).toStdString(),
                  UnitRecordJson::toBytes(*fromLite).toStdString());
        EXPECT_EQ(*fromPg, r);
    }
    // A serial pattern finds the same units on both engines, whatever their LIKE does with case.
    ResultFilter pattern;
    pattern.serial = QStringLiteral("sn-b*");
    const auto pgFound = ResultQueries(*pg).find(pattern, &error);
    const auto liteFound = ResultQueries(*lite).find(pattern, &error);
    ASSERT_TRUE(pgFound && liteFound) << error.toStdString();
    EXPECT_EQ(pgFound->size(), 2);
    EXPECT_EQ(liteFound->size(), 2);
    pattern.serial = QStringLiteral("SN_BOTH*"); // "_" is itself, not any one character
    EXPECT_EQ(ResultQueries(*pg).find(pattern, &error)->size(), 0) << error.toStdString();
}

TEST_F(ResultPostgresTest, MigratesRefusesNewerAndMarksInterrupted)
{
    {
        auto old = open(1);
        ASSERT_TRUE(old);
        EXPECT_FALSE(old->db().tables().contains(QStringLiteral("unit_traffic")));
    }
    auto db = open();
    ASSERT_TRUE(db);
    EXPECT_EQ(db->schemaVersion(), ResultSchema::currentVersion());
    ResultStore store(*db);
    QString error;
    UnitRecord r = test::eolSampleUnit(QStringLiteral("SN-PG-RUN"));
    r.started = QDateTime();
    ASSERT_TRUE(store.beginUnit(r, &error)) << error.toStdString();
    EXPECT_EQ(store.markInterrupted(r.station, QDateTime::currentDateTimeUtc().addSecs(1), &error),
              1)
        << error.toStdString();
    EXPECT_EQ(ResultQueries(*db).load(r.id, &error)->status, UnitStatus::Interrupted);
    // Schema 5 on PostgreSQL: the status CHECK takes station errors, attempts are counted.
    for (UnitStatus status : {UnitStatus::Fail, UnitStatus::Error, UnitStatus::Pass}) {
        UnitRecord u = test::eolSampleUnit(QStringLiteral("SN-PG-ATT"), status);
        u.id.clear();
        u.started = QDateTime();
        ASSERT_TRUE(store.beginUnit(u, &error) && store.finishUnit(u, &error))
            << error.toStdString();
        const auto loaded = ResultQueries(*db).load(u.id, &error);
        ASSERT_TRUE(loaded) << error.toStdString();
        EXPECT_EQ(loaded->status, status);
        EXPECT_EQ(loaded->attempt, status == UnitStatus::Fail ? 1 : 2); // the error is no attempt
    }
    ASSERT_TRUE(
        db->exec(QStringLiteral("INSERT INTO schema_version VALUES (99, 'x', 'y')"), &error));
    EXPECT_FALSE(ResultDatabase::open(url, &error));
    EXPECT_TRUE(error.contains(QLatin1String("99"))) << error.toStdString();
}

TEST_F(ResultPostgresTest, TwoStationProcessesWriteFiftyUnitsEachAtOnce)
{
    QElapsedTimer timer;
    timer.start();
    QProcess a, b;
    for (auto [p, station] : {std::pair{&a, "A"}, std::pair{&b, "B"}})
        p->start(QStringLiteral(OPENTOP_EOL_DB_WRITER),
                 {QStringLiteral("write"), url, QLatin1String(station), QStringLiteral("50")});
    for (QProcess* p : {&a, &b}) {
        ASSERT_TRUE(p->waitForFinished(120000));
        EXPECT_EQ(p->exitStatus(), QProcess::NormalExit);
        EXPECT_EQ(p->exitCode(), 0) << p->readAllStandardError().data();
        EXPECT_EQ(p->readAllStandardOutput().trimmed(), QByteArray("done 50"));
    }
    std::printf("two stations wrote 100 units in %.2f s\n", timer.elapsed() / 1000.0);
    auto db = open();
    ASSERT_TRUE(db);
    QString error;
    const auto units = ResultQueries(*db).find({}, &error);
    ASSERT_TRUE(units) << error.toStdString();
    ASSERT_EQ(units->size(), 100);
    int perStation[2] = {0, 0};
    for (const UnitRecord& u : *units) {
        const auto whole = ResultQueries(*db).load(u.id, &error);
        ASSERT_TRUE(whole);
        ++perStation[u.station == QLatin1String("A") ? 0 : 1];
        EXPECT_TRUE(u.status == UnitStatus::Pass || u.status == UnitStatus::Fail);
        EXPECT_EQ(whole->drives.size(), 2);
        EXPECT_EQ(whole->writtenValues.size(), 3);
        EXPECT_EQ(whole->measurements.size(), 3);
        EXPECT_EQ(whole->traffic.size(), u.status == UnitStatus::Fail ? 2 : 0);
        EXPECT_TRUE(whole->ended.isValid());
    }
    EXPECT_EQ(perStation[0], 50);
    EXPECT_EQ(perStation[1], 50);
    ResultFilter fails;
    fails.status = UnitStatus::Fail;
    EXPECT_EQ(ResultQueries(*db).find(fails, &error)->size(), 20);
}
