#include "model/eol/ResultDatabase.h"
#include "model/eol/ResultQueries.h"
#include "model/eol/ResultSchema.h"
#include "model/eol/ResultStore.h"
#include "model/eol/UnitRecordJson.h"
#include "tests/support/EolSampleUnit.h"

#include <QFile>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QTimeZone>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

class ResultDatabaseTest : public ::testing::Test
{
protected:
    QString path() const { return dir.filePath(QStringLiteral("results.db")); }
    std::unique_ptr<ResultDatabase> open(int version = -1)
    {
        QString error;
        auto db = ResultDatabase::open(path(), &error, version);
        EXPECT_TRUE(db) << error.toStdString();
        return db;
    }
    static QVariant scalar(ResultDatabase& db, const QString& sql)
    {
        QSqlQuery q(db.db());
        EXPECT_TRUE(q.exec(sql) && q.next()) << sql.toStdString();
        return q.value(0);
    }

    QTemporaryDir dir;
};

} // namespace

TEST_F(ResultDatabaseTest, SqliteUsesWalDurableCommitsAndForeignKeys)
{
    auto db = open();
    ASSERT_TRUE(db);
    EXPECT_EQ(scalar(*db, QStringLiteral("PRAGMA journal_mode")).toString(), QStringLiteral("wal"));
    EXPECT_EQ(scalar(*db, QStringLiteral("PRAGMA synchronous")).toInt(), 2); // FULL
    EXPECT_EQ(scalar(*db, QStringLiteral("PRAGMA foreign_keys")).toInt(), 1);
    EXPECT_EQ(scalar(*db, QStringLiteral("PRAGMA busy_timeout")).toInt(),
              ResultDatabase::kBusyTimeoutMs);
    EXPECT_EQ(db->schemaVersion(), ResultSchema::currentVersion());
    EXPECT_EQ(db->integrityCheck(), QStringLiteral("ok"));
    UnitRecord r = test::eolSampleUnit(QStringLiteral("SN-W"));
    QString error;
    ASSERT_TRUE(ResultStore(*db).beginUnit(r, &error)) << error.toStdString();
    EXPECT_TRUE(QFile::exists(path() + QStringLiteral("-wal")));
}

TEST_F(ResultDatabaseTest, EachOpenHasItsOwnConnectionAndOpeningAgainChangesNothing)
{
    auto a = open();
    auto b = open();
    ASSERT_TRUE(a && b);
    EXPECT_NE(a->connectionName(), b->connectionName());
    // One row per migration (versions may leave gaps on a branch), the newest the current one.
    EXPECT_EQ(scalar(*b, QStringLiteral("SELECT COUNT(*) FROM schema_version")).toInt(),
              int(ResultSchema::migrations().size()));
    EXPECT_EQ(scalar(*b, QStringLiteral("SELECT MAX(version) FROM schema_version")).toInt(),
              ResultSchema::currentVersion());
}

TEST_F(ResultDatabaseTest, MigratesAnOlderDatabaseKeepingItsUnits)
{
    {
        auto old = open(1);
        ASSERT_TRUE(old);
        EXPECT_EQ(old->schemaVersion(), 1);
        EXPECT_FALSE(old->db().tables().contains(QStringLiteral("unit_traffic")));
        QString error;
        ASSERT_TRUE(old->exec(
            QStringLiteral("INSERT INTO units VALUES ('u-old', 'SN-OLD', 'st', 'op',"
                           " '2025-01-02T03:04:05.000Z', '2025-01-02T03:05:00.000Z', 'r', '1',"
                           " 'c', 'pass', '')"),
            &error))
            << error.toStdString();
    }
    auto db = open();
    ASSERT_TRUE(db);
    EXPECT_EQ(db->schemaVersion(), ResultSchema::currentVersion());
    EXPECT_TRUE(db->db().tables().contains(QStringLiteral("unit_traffic")));
    QString error;
    const auto old = ResultQueries(*db).load(QStringLiteral("u-old"), &error);
    ASSERT_TRUE(old) << error.toStdString();
    EXPECT_EQ(old->serial, QStringLiteral("SN-OLD"));
    EXPECT_EQ(old->status, UnitStatus::Pass);
    UnitRecord r = test::eolSampleUnit(QStringLiteral("SN-NEW"));
    ResultStore store(*db);
    ASSERT_TRUE(store.beginUnit(r, &error) && store.finishUnit(r, &error)) << error.toStdString();
    EXPECT_EQ(ResultQueries(*db).load(r.id, &error)->traffic, r.traffic);
}

// Schema 5 rebuilds SQLite's units table (a CHECK cannot be changed in place): the rows and
// their children survive, the foreign keys still hold, and the new status is taken.
TEST_F(ResultDatabaseTest, StationErrorsMigrationKeepsUnitsChildrenAndForeignKeys)
{
    QString error;
    UnitRecord before = test::eolSampleUnit(QStringLiteral("SN-V3"));
    {
        auto old = open(3);
        ASSERT_TRUE(old);
        ResultStore store(*old);
        ASSERT_TRUE(store.beginUnit(before, &error) && store.finishUnit(before, &error))
            << error.toStdString();
    }
    auto db = open();
    ASSERT_TRUE(db);
    EXPECT_EQ(db->schemaVersion(), ResultSchema::currentVersion());
    const auto kept = ResultQueries(*db).load(before.id, &error);
    ASSERT_TRUE(kept) << error.toStdString();
    ASSERT_EQ(kept->drives.size(), before.drives.size());
    for (int i = 0; i < before.drives.size(); ++i) { // a version 3 row: no variant source yet
        EXPECT_EQ(kept->drives[i].variant, before.drives[i].variant);
        EXPECT_EQ(kept->drives[i].firmware, before.drives[i].firmware);
    }
    EXPECT_EQ(kept->measurements, before.measurements);
    EXPECT_EQ(kept->attempt, 0) << "recorded before attempts were counted";
    EXPECT_EQ(scalar(*db, QStringLiteral("PRAGMA foreign_keys")).toInt(), 1);
    EXPECT_FALSE(db->exec(QStringLiteral("INSERT INTO unit_drives VALUES ('no-such-unit', 0, 1,"
                                         " 'DBU', 'dbu200', '1')"),
                          &error))
        << "a child of no unit is still refused";
    UnitRecord r = test::eolSampleUnit(QStringLiteral("SN-ERR"), UnitStatus::Error);
    r.failureReason = QStringLiteral("no drive answers at machine number 2");
    ResultStore store(*db);
    ASSERT_TRUE(store.beginUnit(r, &error) && store.finishUnit(r, &error)) << error.toStdString();
    const auto loaded = ResultQueries(*db).load(r.id, &error);
    ASSERT_TRUE(loaded) << error.toStdString();
    EXPECT_EQ(loaded->status, UnitStatus::Error);
    EXPECT_EQ(loaded->attempt, 1);
    EXPECT_EQ(db->integrityCheck(), QStringLiteral("ok"));
}

TEST_F(ResultDatabaseTest, RefusesADatabaseNewerThanTheProgram)
{
    {
        auto db = open();
        ASSERT_TRUE(db);
        QString error;
        ASSERT_TRUE(
            db->exec(QStringLiteral("INSERT INTO schema_version VALUES (99, 'x', 'y')"), &error));
    }
    QString error;
    EXPECT_FALSE(ResultDatabase::open(path(), &error));
    EXPECT_TRUE(error.contains(QLatin1String("99"))) << error.toStdString();
    EXPECT_TRUE(error.contains(QLatin1String("update OpenTOP"))) << error.toStdString();
    EXPECT_TRUE(error.contains(path())) << error.toStdString();
}

TEST_F(ResultDatabaseTest, RefusesAFileThatIsNotADatabase)
{
    QFile file(path());
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(QByteArray(4096, 'x'));
    file.close();
    QString error;
    EXPECT_FALSE(ResultDatabase::open(path(), &error));
    EXPECT_TRUE(error.contains(path())) << error.toStdString();
}

TEST_F(ResultDatabaseTest, RecordRoundTripsWhole)
{
    auto db = open();
    ASSERT_TRUE(db);
    ResultStore store(*db);
    for (UnitStatus status : {UnitStatus::Pass, UnitStatus::Fail, UnitStatus::Aborted}) {
        UnitRecord r = test::eolSampleUnit(QStringLiteral("SN-RT"), status);
        r.started = QDateTime();
        r.ended = QDateTime();
        QString error;
        ASSERT_TRUE(store.beginUnit(r, &error)) << error.toStdString();
        EXPECT_FALSE(r.id.isEmpty());
        EXPECT_TRUE(r.started.isValid());
        const auto running = ResultQueries(*db).load(r.id, &error);
        ASSERT_TRUE(running);
        EXPECT_EQ(running->status, UnitStatus::Running);
        EXPECT_TRUE(running->measurements.isEmpty());
        r.status = status;
        ASSERT_TRUE(store.finishUnit(r, &error)) << error.toStdString();
        const auto back = ResultQueries(*db).load(r.id, &error);
        ASSERT_TRUE(back) << error.toStdString();
        EXPECT_EQ(UnitRecordJson::toBytes(*back).toStdString(),
                  UnitRecordJson::toBytes(r).toStdString());
        EXPECT_EQ(*back, r);
    }
}

TEST_F(ResultDatabaseTest, FinishNeedsARunningUnitAndAFinalStatus)
{
    auto db = open();
    ASSERT_TRUE(db);
    ResultStore store(*db);
    QString error;
    UnitRecord never = test::eolSampleUnit(QStringLiteral("SN-N"));
    never.id = QStringLiteral("not-begun");
    EXPECT_FALSE(store.finishUnit(never, &error));
    EXPECT_TRUE(error.contains(QLatin1String("never begun"))) << error.toStdString();
    UnitRecord r = test::eolSampleUnit(QStringLiteral("SN-F"), UnitStatus::Pass);
    ASSERT_TRUE(store.beginUnit(r, &error));
    r.status = UnitStatus::Running;
    EXPECT_FALSE(store.finishUnit(r, &error));
    r.status = UnitStatus::Pass;
    ASSERT_TRUE(store.finishUnit(r, &error)) << error.toStdString();
    r.status =
        UnitStatus::Fail; // a second finish must not turn a recorded PASS into something else
    EXPECT_FALSE(store.finishUnit(r, &error));
    EXPECT_EQ(ResultQueries(*db).load(r.id, &error)->status, UnitStatus::Pass);
    // the refused finish left no extra child rows behind
    EXPECT_EQ(scalar(*db, QStringLiteral("SELECT COUNT(*) FROM measurements")).toInt(),
              r.measurements.size());
    UnitRecord noSerial;
    EXPECT_FALSE(store.beginUnit(noSerial, &error));
}

TEST_F(ResultDatabaseTest, MarkInterruptedTouchesOnlyThisStationsOlderRunningUnits)
{
    auto db = open();
    ASSERT_TRUE(db);
    ResultStore store(*db);
    QString error;
    const QDateTime restart(QDate(2026, 11, 24), QTime(14, 0), QTimeZone::utc());
    auto begin = [&](const QString& serial, const QString& station, const QDateTime& at) {
        UnitRecord r = test::eolSampleUnit(serial);
        r.station = station;
        r.started = at;
        EXPECT_TRUE(store.beginUnit(r, &error)) << error.toStdString();
        return r;
    };
    UnitRecord left = begin(QStringLiteral("A1"), QStringLiteral("A"), restart.addSecs(-60));
    UnitRecord other = begin(QStringLiteral("B1"), QStringLiteral("B"), restart.addSecs(-60));
    UnitRecord fresh = begin(QStringLiteral("A2"), QStringLiteral("A"), restart.addSecs(1));
    UnitRecord done = begin(QStringLiteral("A3"), QStringLiteral("A"), restart.addSecs(-120));
    done.status = UnitStatus::Pass;
    ASSERT_TRUE(store.finishUnit(done, &error));
    EXPECT_EQ(store.markInterrupted(QStringLiteral("A"), restart, &error), 1);
    ResultQueries queries(*db);
    EXPECT_EQ(queries.load(left.id, &error)->status, UnitStatus::Interrupted);
    EXPECT_EQ(queries.load(left.id, &error)->failureReason, ResultStore::interruptedReason());
    EXPECT_EQ(queries.load(other.id, &error)->status, UnitStatus::Running);
    EXPECT_EQ(queries.load(fresh.id, &error)->status, UnitStatus::Running);
    EXPECT_EQ(queries.load(done.id, &error)->status, UnitStatus::Pass);
    // an interrupted unit can no longer be finished as a pass
    left.status = UnitStatus::Pass;
    EXPECT_FALSE(store.finishUnit(left, &error));
    EXPECT_EQ(store.markInterrupted(QStringLiteral("A"), restart, &error), 0);
}
