// Two station processes writing to one SQLite file at once: the second waits for the first's
// write lock (BEGIN IMMEDIATE, busy timeout) instead of failing, and every unit is whole.
#include "model/eol/ResultDatabase.h"
#include "model/eol/ResultQueries.h"
#include "tests/support/EolSampleUnit.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QTemporaryDir>
#include <gtest/gtest.h>

using namespace opentop;

TEST(ResultConcurrencyTest, TwoStationProcessesShareOneSqliteFile)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("shared.db"));
    QElapsedTimer timer;
    timer.start();
    QProcess a, b;
    for (auto [p, station] : {std::pair{&a, "A"}, std::pair{&b, "B"}})
        p->start(QStringLiteral(OPENTOP_EOL_DB_WRITER),
                 {QStringLiteral("write"), path, QLatin1String(station), QStringLiteral("50")});
    for (QProcess* p : {&a, &b}) {
        ASSERT_TRUE(p->waitForFinished(120000));
        EXPECT_EQ(p->exitCode(), 0) << p->readAllStandardError().data();
    }
    std::printf("two stations wrote 100 units to one SQLite file in %.2f s\n",
                timer.elapsed() / 1000.0);
    QString error;
    auto db = ResultDatabase::open(path, &error);
    ASSERT_TRUE(db) << error.toStdString();
    EXPECT_EQ(db->integrityCheck(), QStringLiteral("ok"));
    const auto units = ResultQueries(*db).find({}, &error);
    ASSERT_TRUE(units);
    ASSERT_EQ(units->size(), 100);
    for (const UnitRecord& u : *units) {
        const auto whole = ResultQueries(*db).load(u.id, &error);
        ASSERT_TRUE(whole);
        EXPECT_NE(u.status, UnitStatus::Running);
        EXPECT_EQ(whole->measurements.size(), 3);
    }
}
