// A station killed with SIGKILL inside finishUnit's transaction (every child row written, the
// status not yet): the database stays valid, the unit stays 'running', the station's restart
// marks it 'interrupted', and no query ever counts it as a pass.
#include "model/eol/ResultDatabase.h"
#include "model/eol/ResultQueries.h"
#include "model/eol/ResultStore.h"
#include "model/eol/YieldReport.h"
#include "tests/support/EolSampleUnit.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <gtest/gtest.h>
#include <signal.h>

using namespace opentop;

namespace {

int count(ResultDatabase& db, const QString& sql)
{
    QSqlQuery q(db.db());
    EXPECT_TRUE(q.exec(sql) && q.next()) << sql.toStdString();
    return q.value(0).toInt();
}

} // namespace

TEST(ResultKillTest, KilledInsideFinishLeavesARunningUnitThatBecomesInterruptedNeverPass)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("kill.db"));
    QProcess station;
    station.start(QStringLiteral(OPENTOP_EOL_DB_WRITER),
                  {QStringLiteral("hang"), path, QStringLiteral("st-1"), QStringLiteral("SN-K")});
    ASSERT_TRUE(station.waitForStarted(10000));
    QByteArray out;
    QElapsedTimer timer;
    timer.start();
    while (!out.contains("in-transaction") && timer.elapsed() < 30000 &&
           station.state() == QProcess::Running) {
        station.waitForReadyRead(500);
        out += station.readAllStandardOutput();
    }
    ASSERT_TRUE(out.contains("in-transaction"))
        << out.data() << station.readAllStandardError().data();
    const QString id = QString::fromUtf8(out.mid(6, out.indexOf('\n') - 6)); // "begun ID\n"
    // While the killed-to-be station holds its write transaction, its children are invisible.
    ASSERT_EQ(::kill(pid_t(station.processId()), SIGKILL), 0);
    ASSERT_TRUE(station.waitForFinished(10000));
    EXPECT_EQ(station.exitStatus(), QProcess::CrashExit);

    QString error;
    auto db = ResultDatabase::open(path, &error);
    ASSERT_TRUE(db) << error.toStdString();
    EXPECT_EQ(db->integrityCheck(), QStringLiteral("ok"));
    ResultQueries queries(*db);
    auto unit = queries.load(id, &error);
    ASSERT_TRUE(unit) << error.toStdString() << " id " << id.toStdString();
    EXPECT_EQ(unit->serial, QStringLiteral("SN-K"));
    EXPECT_EQ(unit->status, UnitStatus::Running);
    // nothing of the half-written finish is there
    EXPECT_TRUE(unit->drives.isEmpty());
    EXPECT_TRUE(unit->measurements.isEmpty());
    EXPECT_EQ(count(*db, QStringLiteral("SELECT COUNT(*) FROM written_values")), 0);
    ResultFilter passes;
    passes.status = UnitStatus::Pass;
    EXPECT_TRUE(queries.find(passes, &error)->isEmpty());

    // The station starts again: its leftover becomes 'interrupted'.
    ResultStore store(*db);
    EXPECT_EQ(
        store.markInterrupted(QStringLiteral("st-1"), QDateTime::currentDateTimeUtc(), &error), 1);
    unit = queries.load(id, &error);
    EXPECT_EQ(unit->status, UnitStatus::Interrupted);
    EXPECT_FALSE(unit->failureReason.isEmpty());
    EXPECT_TRUE(queries.find(passes, &error)->isEmpty());
    const auto rows = YieldReport::perRecipe(*queries.find({}, &error));
    ASSERT_EQ(rows.size(), 1);
    EXPECT_EQ(rows[0].firstPass, 0);
    EXPECT_EQ(rows[0].running, 1);
    EXPECT_EQ(db->integrityCheck(), QStringLiteral("ok"));
}

TEST(ResultKillTest, AStationThatFinishesWritesWholeUnits)
{
    // The same helper, not killed: every unit complete (proves the kill test's helper works).
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("ok.db"));
    QProcess station;
    station.start(QStringLiteral(OPENTOP_EOL_DB_WRITER),
                  {QStringLiteral("write"), path, QStringLiteral("st-2"), QStringLiteral("10")});
    ASSERT_TRUE(station.waitForFinished(60000));
    ASSERT_EQ(station.exitCode(), 0) << station.readAllStandardError().data();
    QString error;
    auto db = ResultDatabase::open(path, &error);
    ASSERT_TRUE(db);
    EXPECT_EQ(count(*db, QStringLiteral("SELECT COUNT(*) FROM units WHERE status IN "
                                        "('pass', 'fail')")),
              10);
    EXPECT_EQ(count(*db, QStringLiteral("SELECT COUNT(*) FROM measurements")), 30);
    EXPECT_EQ(count(*db, QStringLiteral("SELECT COUNT(*) FROM units WHERE status = 'fail'")), 2);
}
