#include "model/eol/ResultQueries.h"
#include "model/eol/ResultDatabase.h"
#include "model/eol/ResultStore.h"
#include "model/eol/YieldReport.h"
#include "tests/support/EolSampleUnit.h"

#include <QTemporaryDir>
#include <QTimeZone>
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
    const QDateTime t0{QDate(2026, 11, 24), QTime(8, 0), QTimeZone::utc()};
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

TEST_F(ResultQueriesTest, AttemptsCountTheSerialsVerdictsUnderItsRecipe)
{
    QString error;
    const auto history = ResultQueries(*db).history(QStringLiteral("S2"), &error);
    ASSERT_TRUE(history) << error.toStdString();
    ASSERT_EQ(history->size(), 2);
    EXPECT_EQ(history->at(0).attempt, 1);
    EXPECT_EQ(history->at(1).attempt, 2); // after its fail
    const auto h = ResultQueries(*db).serialHistory(QStringLiteral("S2"),
                                                    history->at(0).recipeChecksum, &error);
    ASSERT_TRUE(h) << error.toStdString();
    EXPECT_EQ(h->verdicts, 2);
    EXPECT_EQ(h->failures, 1);
    EXPECT_TRUE(h->passedAny);
    const auto other = ResultQueries(*db).serialHistory(QStringLiteral("S2"),
                                                        QStringLiteral("sha256:other"), &error);
    EXPECT_EQ(other->verdicts, 0); // attempts are per recipe version
    EXPECT_TRUE(other->passedAny); // a pass is a pass under any recipe
    // An aborted unit is no verdict: the next test of S5 is still its first.
    const auto s5 = ResultQueries(*db).history(QStringLiteral("S5"), &error);
    ASSERT_EQ(s5->size(), 1);
    EXPECT_EQ(s5->at(0).attempt, 1);
    const auto earlier = ResultQueries(*db).earlierOf(history->at(1), &error);
    ASSERT_TRUE(earlier) << error.toStdString();
    ASSERT_EQ(earlier->size(), 1);
    EXPECT_EQ(earlier->at(0).status, UnitStatus::Fail);
}

TEST_F(ResultQueriesTest, TestedBeforeNamesTheRangesRetestsOnly)
{
    ResultFilter f;
    f.from = t0.addSecs(15 * 60); // S2 was first tested at 10 min, retested at 20
    QString error;
    const auto earlier = ResultQueries(*db).testedBefore(f, &error);
    ASSERT_TRUE(earlier) << error.toStdString();
    const QString sum = test::eolSampleUnit(QStringLiteral("x"), UnitStatus::Pass).recipeChecksum;
    ASSERT_EQ(earlier->size(), 1);
    EXPECT_EQ(earlier->value({sum, QStringLiteral("S2")}).verdicts, 1);
    EXPECT_FALSE(earlier->value({sum, QStringLiteral("S2")}).passed);
    const auto units = ResultQueries(*db).find(f, &error);
    const auto rows = YieldReport::perRecipe(*units, *earlier);
    ASSERT_EQ(rows.size(), 2);
    EXPECT_EQ(rows[1].recipe, QStringLiteral("pump"));
    EXPECT_EQ(rows[1].serials, 0); // S2's retest is not a first test; S4 has no verdict yet
    EXPECT_EQ(rows[1].passed, 1);
    EXPECT_EQ(rows[1].running, 1);
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
