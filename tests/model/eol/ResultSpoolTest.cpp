// The station's spool: results a results database cannot take are kept on the station's disk
// and reach the database in order and exactly once when it answers again, against a real
// PostgreSQL server that the test stops and starts (PostgresServer).
#include "model/eol/ResultSpool.h"
#include "model/eol/ResultDatabase.h"
#include "model/eol/ResultQueries.h"
#include "model/eol/ResultSink.h"
#include "model/eol/ResultStore.h"
#include "model/eol/ResultWriter.h"
#include "tests/support/EolSampleUnit.h"
#include "tests/support/PostgresServer.h"

#include <QElapsedTimer>
#include <QEventLoop>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QTimer>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

bool spinUntil(const std::function<bool()>& done, int ms)
{
    QElapsedTimer clock;
    clock.start();
    while (!done() && clock.elapsed() < ms) {
        QEventLoop loop;
        QTimer::singleShot(10, &loop, &QEventLoop::quit);
        loop.exec();
    }
    return done();
}

int rowsOf(ResultDatabase& db, const QString& serial)
{
    QSqlQuery q(db.db());
    q.prepare(QStringLiteral("SELECT COUNT(*) FROM units WHERE serial = ?"));
    q.addBindValue(serial);
    return q.exec() && q.next() ? q.value(0).toInt() : -1;
}

class ResultSpoolTest : public ::testing::Test
{
protected:
    void SetUp() override
    {
        ASSERT_TRUE(folder.isValid());
        if (test::PostgresServer::skipRequested())
            GTEST_SKIP() << "OPENTOP_TEST_PG_SKIP=1: PostgreSQL tests skipped on request";
        QString error;
        server = test::PostgresServer::shared(&error);
        ASSERT_TRUE(server) << "cannot start a PostgreSQL server for the tests: "
                            << error.toStdString();
        url = server->createDatabase(
            QStringLiteral("spool_%1")
                .arg(QString::fromLatin1(
                         ::testing::UnitTest::GetInstance()->current_test_info()->name())
                         .toLower()),
            &error);
        ASSERT_FALSE(url.isEmpty()) << error.toStdString();
    }
    std::unique_ptr<ResultDatabase> open()
    {
        QString error;
        auto db = ResultDatabase::open(url, &error);
        EXPECT_TRUE(db) << error.toStdString();
        return db;
    }
    UnitRecord unit(const QString& serial)
    {
        UnitRecord r = test::eolSampleUnit(serial, UnitStatus::Pass);
        r.id.clear();
        r.started = QDateTime();
        r.station = QStringLiteral("line 1");
        return r;
    }

    QTemporaryDir folder;
    test::PostgresServer* server = nullptr;
    QString url;
};

} // namespace

TEST_F(ResultSpoolTest, AServerThatGoesAwayMidUnitGetsEveryRecordInOrderOnceItIsBack)
{
    ResultWriter writer;
    writer.setSpoolFolder(folder.path());
    const ResultWriter::Opened opened = writer.openAndWait(url, QStringLiteral("line 1"));
    ASSERT_TRUE(opened.ok) << qPrintable(opened.error);
    EXPECT_EQ(opened.waiting, 0);
    QObject context;
    auto begin = [&](const UnitRecord& r, ResultWriter::Saved* saved) {
        UnitRecord begun;
        bool answered = false;
        writer.beginUnit(r, &context, [&](const UnitRecord& b, const ResultWriter::Saved& s) {
            begun = b;
            *saved = s;
            answered = true;
        });
        EXPECT_TRUE(spinUntil([&] { return answered; }, 20000));
        return begun;
    };
    auto finish = [&](const UnitRecord& r) {
        ResultWriter::Saved saved;
        bool answered = false;
        writer.finishUnit(r, &context, [&](const ResultWriter::Saved& s) {
            saved = s;
            answered = true;
        });
        EXPECT_TRUE(spinUntil([&] { return answered; }, 20000));
        return saved;
    };

    ResultWriter::Saved saved;
    UnitRecord first = begin(unit(QStringLiteral("SN-S1")), &saved);
    ASSERT_TRUE(saved.error.isEmpty()) << qPrintable(saved.error);
    EXPECT_FALSE(saved.spooled);

    QString error;
    ASSERT_TRUE(server->stopServer(&error)) << qPrintable(error);
    first.status = UnitStatus::Pass;
    saved = finish(first);
    EXPECT_TRUE(saved.error.isEmpty()) << qPrintable(saved.error);
    EXPECT_TRUE(saved.spooled) << "the verdict is kept on the station's disk";
    EXPECT_FALSE(saved.why.isEmpty());
    UnitRecord second = begin(unit(QStringLiteral("SN-S2")), &saved);
    EXPECT_TRUE(saved.spooled);
    EXPECT_FALSE(second.id.isEmpty()) << "the spool keeps the id the database will have";
    second.status = UnitStatus::Fail;
    second.failureReason = QStringLiteral("speed low");
    EXPECT_TRUE(finish(second).spooled);
    ASSERT_TRUE(spinUntil([&] { return writer.waiting() == 3; }, 5000)) << writer.waiting();
    EXPECT_FALSE(writer.waitingError().isEmpty());

    ASSERT_TRUE(server->startServer(&error)) << qPrintable(error);
    writer.flushNow();
    ASSERT_TRUE(spinUntil([&] { return writer.waiting() == 0; }, 20000)) << writer.waiting();
    auto db = open();
    ASSERT_TRUE(db);
    EXPECT_EQ(rowsOf(*db, QStringLiteral("SN-S1")), 1);
    EXPECT_EQ(rowsOf(*db, QStringLiteral("SN-S2")), 1);
    const auto one = ResultQueries(*db).load(first.id, &error);
    const auto two = ResultQueries(*db).load(second.id, &error);
    ASSERT_TRUE(one && two) << qPrintable(error);
    EXPECT_EQ(one->status, UnitStatus::Pass);
    EXPECT_EQ(two->status, UnitStatus::Fail);
    EXPECT_EQ(two->failureReason, QStringLiteral("speed low"));
    EXPECT_EQ(two->measurements.size(), second.measurements.size());
    EXPECT_LT(one->started, two->started);
}

TEST_F(ResultSpoolTest, AnEntrySentTwiceAfterAKillIsInTheDatabaseOnce)
{
    QString error;
    ResultSink sink;
    ASSERT_TRUE(sink.open(url, QStringLiteral("line 1"), folder.path(), &error))
        << qPrintable(error);
    ASSERT_TRUE(server->stopServer(&error)) << qPrintable(error);
    UnitRecord r = unit(QStringLiteral("SN-K1"));
    EXPECT_TRUE(sink.begin(r).spooled);
    r.status = UnitStatus::Pass;
    EXPECT_TRUE(sink.finish(r).spooled);
    ASSERT_TRUE(server->startServer(&error)) << qPrintable(error);
    ResultSink::Flushed f = sink.flush();
    EXPECT_EQ(f.sent, 2);
    EXPECT_EQ(f.waiting, 0) << qPrintable(f.error);

    // As if the station was killed after the database committed and before the spool forgot:
    // the same entries come again.
    auto spool = ResultSpool::open(folder.path(), url, &error);
    ASSERT_TRUE(spool) << qPrintable(error);
    ASSERT_TRUE(spool->append(ResultSpool::Kind::Begin, r, QStringLiteral("gone"), &error));
    ASSERT_TRUE(spool->append(ResultSpool::Kind::Finish, r, QStringLiteral("gone"), &error));
    f = sink.flush();
    EXPECT_EQ(f.waiting, 0) << qPrintable(f.error);
    auto db = open();
    ASSERT_TRUE(db);
    EXPECT_EQ(rowsOf(*db, QStringLiteral("SN-K1")), 1);
    EXPECT_EQ(ResultStore(*db).statusOf(r.id, &error), QStringLiteral("pass"));
}

TEST_F(ResultSpoolTest, ARecordTheDatabaseRefusesStaysInTheSpoolNamed)
{
    QString error;
    {
        auto spool = ResultSpool::open(folder.path(), url, &error);
        ASSERT_TRUE(spool) << qPrintable(error);
        UnitRecord never = unit(QStringLiteral("SN-R1"));
        ResultStore::identify(never);
        never.status = UnitStatus::Pass;
        ASSERT_TRUE(spool->append(ResultSpool::Kind::Finish, never, QString(), &error));
    }
    ResultWriter writer;
    writer.setSpoolFolder(folder.path());
    const ResultWriter::Opened opened = writer.openAndWait(url, QStringLiteral("line 1"));
    ASSERT_TRUE(opened.ok) << qPrintable(opened.error);
    EXPECT_EQ(opened.waiting, 1) << "kept, never dropped";
    ASSERT_TRUE(
        spinUntil([&] { return writer.waitingError().contains(QLatin1String("SN-R1")); }, 5000))
        << qPrintable(writer.waitingError());
}

TEST(ResultSpoolFileTest, EntriesSurviveTheProcessAndEachDatabaseHasItsOwnFile)
{
    QTemporaryDir folder;
    QString error;
    UnitRecord r = test::eolSampleUnit(QStringLiteral("SN-F1"), UnitStatus::Pass);
    const QString a = QStringLiteral("postgresql://eol:secret@db.factory/results");
    {
        auto spool = ResultSpool::open(folder.path(), a, &error);
        ASSERT_TRUE(spool) << qPrintable(error);
        EXPECT_FALSE(spool->path().contains(QLatin1String("secret")));
        ASSERT_TRUE(spool->append(ResultSpool::Kind::Begin, r, QStringLiteral("L1"), &error))
            << qPrintable(error);
        ASSERT_TRUE(spool->append(ResultSpool::Kind::Finish, r, QStringLiteral("L1"), &error));
    }
    auto again = ResultSpool::open(folder.path(), a, &error);
    ASSERT_TRUE(again) << qPrintable(error);
    EXPECT_EQ(again->count(), 2);
    const auto oldest = again->oldest(&error);
    ASSERT_TRUE(oldest) << qPrintable(error);
    EXPECT_EQ(oldest->kind, ResultSpool::Kind::Begin);
    EXPECT_EQ(oldest->lease, QStringLiteral("L1"));
    EXPECT_EQ(oldest->record, r);
    ASSERT_TRUE(again->remove(oldest->seq, &error));
    EXPECT_EQ(again->oldest(&error)->kind, ResultSpool::Kind::Finish);

    auto other =
        ResultSpool::open(folder.path(), QStringLiteral("postgresql://db.factory/other"), &error);
    ASSERT_TRUE(other) << qPrintable(error);
    EXPECT_NE(other->path(), again->path());
    EXPECT_EQ(other->count(), 0);
}
