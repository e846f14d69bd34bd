#include "eol/ResultQueries.h"
#include "EolSampleUnit.h"
#include "eol/ResultDatabase.h"
#include "eol/ResultStore.h"
#include "eol/YieldReport.h"

#include <QTemporaryDir>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

class ResultQueriesTest : public ::testing::Test
{
protected:
    void SetUp() override
    {
        QString error;
        db = ResultDatabase::open(dir.filePath(QStringLiteral("q.db")), &error);
        ASSERT_TRUE(db) << error.toStdString();
        ResultStore store(*db);
        // serial, station, recipe, minutes after t0, final status (Running: left running)
        const struct
        {
            const char* serial;
            const char* station;
            const char* recipe;
            int minute;
            UnitStatus status;
        } units[] = {
            {"S1", "A", "pump", 0, UnitStatus::Pass},
            {"S2", "A", "pump", 10, UnitStatus::Fail},
            {"S2", "B", "pump", 20, UnitStatus::Pass},
            {"S3", "B", "fan", 30, UnitStatus::Pass},
            {"S4", "A", "pump", 40, UnitStatus::Running},
            {"S5", "B", "fan", 50, UnitStatus::Aborted},
        };
        for (const auto& u : units) {
            UnitRecord r = test::eolSampleUnit(QLatin1String(u.serial), u.status);
            r.station = QLatin1String(u.station);
            r.recipeName = QLatin1String(u.recipe);
            r.started = t0.addSecs(60 * u.minute);
            r.ended = r.started.addSecs(30);
            ASSERT_TRUE(store.beginUnit(r, &error)) << error.toStdString();
            if (u.status != UnitStatus::Running) {
                ASSERT_TRUE(store.finishUnit(r, &error)) << error.toStdString();
            }
        }
    }
    QStringList serials(const ResultFilter& filter)
    {
        QString error;
        const auto found = ResultQueries(*db).find(filter, &error);
        EXPECT_TRUE(found) << error.toStdString();
        QStringList list;
        for (const UnitRecord& r : found.value_or(QVector<UnitRecord>()))
            list.append(r.serial + QLatin1Char('/') + unitStatusName(r.status));
        return list;
    }

    QTemporaryDir dir;
    std::unique_ptr<ResultDatabase> db;
    const QDateTime t0{QDate(2026, 11, 24), QTime(8, 0), Qt::UTC};
};

QStringList list(std::initializer_list<const char*> items)
{
    QStringList l;
    for (const char* i : items)
        l.append(QLatin1String(i));
    return l;
}

} // namespace

TEST_F(ResultQueriesTest, FiltersBySerialTimeRecipeVerdictAndStation)
{
    EXPECT_EQ(serials({}),
              list({"S1/pass", "S2/fail", "S2/pass", "S3/pass", "S4/running", "S5/aborted"}));
    ResultFilter f;
    f.serial = QStringLiteral("S2");
    EXPECT_EQ(serials(f), list({"S2/fail", "S2/pass"}));
    f = {};
    f.from = t0.addSecs(600);
    f.to = t0.addSecs(1800); // end is exclusive
    EXPECT_EQ(serials(f), list({"S2/fail", "S2/pass"}));
    f = {};
    f.recipe = QStringLiteral("fan");
    EXPECT_EQ(serials(f), list({"S3/pass", "S5/aborted"}));
    f = {};
    f.station = QStringLiteral("A");
    EXPECT_EQ(serials(f), list({"S1/pass", "S2/fail", "S4/running"}));
    f = {};
    f.status = UnitStatus::Pass; // a running unit is never among the passes
    EXPECT_EQ(serials(f), list({"S1/pass", "S2/pass", "S3/pass"}));
    f.station = QStringLiteral("B");
    f.recipe = QStringLiteral("pump");
    EXPECT_EQ(serials(f), list({"S2/pass"}));
    // Issue 25 item 6: what an operator types into a search field.
    f = {};
    f.serial = QStringLiteral("s*");
    EXPECT_EQ(serials(f),
              list({"S1/pass", "S2/fail", "S2/pass", "S3/pass", "S4/running", "S5/aborted"}));
    f.serial = QStringLiteral("?2");
    EXPECT_EQ(serials(f), list({"S2/fail", "S2/pass"}));
    f.serial = QStringLiteral("S_*"); // an underscore is itself, not any character
    EXPECT_EQ(serials(f), QStringList());
    f.serial = QStringLiteral("s2"); // no wildcard: exact, as a certificate needs
    EXPECT_EQ(serials(f), QStringList());
    f = {};
    f.limit = 2; // the newest two, oldest first
    EXPECT_EQ(serials(f), list({"S4/running", "S5/aborted"}));
}

TEST_F(ResultQueriesTest, FilterValuesAreBoundNotPasted)
{
    ResultFilter f;
    f.serial = QStringLiteral("S1' OR '1'='1");
    EXPECT_TRUE(serials(f).isEmpty());
}

TEST_F(ResultQueriesTest, HistoryOfASerialIsWholeAndLoadOfAnUnknownIdSaysSo)
{
    QString error;
    const auto history = ResultQueries(*db).history(QStringLiteral("S2"), &error);
    ASSERT_TRUE(history) << error.toStdString();
    ASSERT_EQ(history->size(), 2);
    EXPECT_EQ(history->at(0).status, UnitStatus::Fail);
    EXPECT_EQ(history->at(0).measurements.size(), 4);
    EXPECT_EQ(history->at(0).traffic.size(), 3);
    EXPECT_EQ(history->at(1).drives.size(), 2);
    EXPECT_FALSE(ResultQueries(*db).load(QStringLiteral("nope"), &error));
    EXPECT_TRUE(error.contains(QLatin1String("nope")));
}

TEST_F(ResultQueriesTest, TestedBeforeNamesTheRangesRetestsOnly)
{
    ResultFilter f;
    f.from = t0.addSecs(15 * 60); // S2 was first tested at 10 min, retested at 20
    QString error;
    const auto earlier = ResultQueries(*db).testedBefore(f, &error);
    ASSERT_TRUE(earlier) << error.toStdString();
    EXPECT_EQ(*earlier, (YieldReport::Earlier{{QStringLiteral("pump"), QStringLiteral("S2")}}));
    const auto units = ResultQueries(*db).find(f, &error);
    const auto rows = YieldReport::perRecipe(*units, *earlier);
    ASSERT_EQ(rows.size(), 2);
    EXPECT_EQ(rows[1].recipe, QStringLiteral("pump"));
    EXPECT_EQ(rows[1].serials, 1); // S4 (running): S2's retest is not a first record
    EXPECT_EQ(rows[1].firstPass, 0);
    f.recipe = QStringLiteral("fan");
    EXPECT_TRUE(ResultQueries(*db).testedBefore(f, &error)->isEmpty());
    EXPECT_TRUE(ResultQueries(*db).testedBefore({}, &error)->isEmpty());
}

// A failed unit retested at once (a fast station, or a script) must stay the first record of
// its serial: the start times of one station never tie, so the order is never left to the
// random unit ids (seen in CI: a retest in the same millisecond counted as a first pass).
TEST(ResultOrderTest, UnitsBegunInOneMillisecondKeepTheOrderTheyWereBegunIn)
{
    QTemporaryDir dir;
    QString error;
    auto db = ResultDatabase::open(dir.filePath(QStringLiteral("o.db")), &error);
    ASSERT_TRUE(db) << error.toStdString();
    ResultStore store(*db);
    const int serials = 40;
    for (int i = 0; i < serials; ++i) {
        for (UnitStatus status : {UnitStatus::Fail, UnitStatus::Pass}) {
            UnitRecord r = test::eolSampleUnit(QStringLiteral("R%1").arg(i), status);
            r.id.clear();
            r.started = QDateTime();
            r.ended = QDateTime();
            ASSERT_TRUE(store.beginUnit(r, &error)) << error.toStdString();
            ASSERT_TRUE(store.finishUnit(r, &error)) << error.toStdString();
        }
    }
    const auto units = ResultQueries(*db).find({}, &error);
    ASSERT_TRUE(units) << error.toStdString();
    ASSERT_EQ(units->size(), 2 * serials);
    for (int i = 1; i < units->size(); ++i)
        EXPECT_LT(units->at(i - 1).started, units->at(i).started)
            << i << ' ' << qPrintable(units->at(i).started.toString(Qt::ISODateWithMs));
    const auto rows = YieldReport::perRecipe(*units);
    ASSERT_EQ(rows.size(), 1);
    EXPECT_EQ(rows[0].serials, serials);
    EXPECT_EQ(rows[0].firstPass, 0); // every serial failed first
}
