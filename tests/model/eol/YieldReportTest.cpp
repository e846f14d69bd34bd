#include "model/eol/YieldReport.h"
#include "model/eol/ResultCsv.h"

#include <QTimeZone>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

UnitRecord unit(const char* serial, const char* recipe, const QDateTime& started, UnitStatus status,
                const char* reason = "")
{
    UnitRecord r;
    r.serial = QLatin1String(serial);
    r.recipeName = QLatin1String(recipe);
    r.recipeRevision = QStringLiteral("A");
    r.recipeChecksum = QStringLiteral("sha256:") + QLatin1String(recipe);
    r.started = started;
    r.status = status;
    r.failureReason = QString::fromUtf8(reason);
    return r;
}

const QDateTime day(QDate(2026, 11, 24), QTime(0, 0), QTimeZone::utc());

QDateTime at(int hour, int minute = 0, int dayOffset = 0)
{
    return day.addDays(dayOffset).addSecs(hour * 3600 + minute * 60);
}

ShiftPlan utcShifts()
{
    return ShiftPlan({QTime(6, 0), QTime(14, 0), QTime(22, 0)}, QTimeZone::utc());
}

} // namespace

TEST(ShiftPlanTest, ShiftsStartAtTheirBoundariesAndTheNightShiftRunsPastMidnight)
{
    const ShiftPlan plan = utcShifts();
    EXPECT_EQ(plan.shiftName(at(6)), QStringLiteral("2026-11-24 06:00"));
    EXPECT_EQ(plan.shiftName(at(13, 59)), QStringLiteral("2026-11-24 06:00"));
    EXPECT_EQ(plan.shiftName(at(14)), QStringLiteral("2026-11-24 14:00"));
    EXPECT_EQ(plan.shiftName(at(23, 30)), QStringLiteral("2026-11-24 22:00"));
    EXPECT_EQ(plan.shiftName(at(2, 0, 1)), QStringLiteral("2026-11-24 22:00"));
    EXPECT_EQ(plan.shiftName(at(5, 59, 1)), QStringLiteral("2026-11-24 22:00"));
    // the plan's zone, not UTC: 05:30 UTC is 06:30 in Berlin in winter
    const ShiftPlan berlin({QTime(6, 0), QTime(18, 0)}, QTimeZone("Europe/Berlin"));
    EXPECT_EQ(berlin.shiftName(at(5, 30)), QStringLiteral("2026-11-24 06:00"));
    EXPECT_EQ(berlin.shiftName(at(4, 30)), QStringLiteral("2026-11-23 18:00"));
}

TEST(ShiftPlanTest, ParsesAndRefusesBoundaryLists)
{
    QString error;
    const auto plan =
        ShiftPlan::parse(QStringLiteral("6:00, 14:00,22:00"), QTimeZone::utc(), &error);
    ASSERT_TRUE(plan) << error.toStdString();
    EXPECT_EQ(plan->boundaries().size(), 3);
    EXPECT_FALSE(ShiftPlan::parse(QStringLiteral("14:00,06:00"), QTimeZone::utc(), &error));
    EXPECT_FALSE(ShiftPlan::parse(QStringLiteral("25:00"), QTimeZone::utc(), &error));
    EXPECT_TRUE(error.contains(QLatin1String("25:00")));
    EXPECT_FALSE(ShiftPlan::parse(QString(), QTimeZone::utc(), &error));
}

TEST(YieldReportTest, TheFirstVerdictPerSerialAndRecipeDecidesAndStationErrorsAreNotVerdicts)
{
    const QVector<UnitRecord> units{
        unit("S1", "pump", at(7), UnitStatus::Pass),
        unit("S2", "pump", at(8), UnitStatus::Fail, "speed low"),
        unit("S2", "pump", at(9), UnitStatus::Pass), // retest: not a first pass
        unit("S3", "pump", at(10), UnitStatus::Running),
        unit("S4", "pump", at(11), UnitStatus::Interrupted), // the station was killed
        unit("S4", "pump", at(12), UnitStatus::Pass),        // its first verdict
        unit("S5", "pump", at(13), UnitStatus::Aborted),
        unit("S6", "pump", at(13, 30), UnitStatus::Error, "no drive answers"),
        unit("S6", "pump", at(13, 40), UnitStatus::Fail, "load high"),
        unit("S1", "fan", at(7, 30), UnitStatus::Pass), // another recipe: its own first record
        unit("S7", "fan", at(8, 30), UnitStatus::Fail, "speed low"),
    };
    const auto rows = YieldReport::perRecipe(units);
    ASSERT_EQ(rows.size(), 2);
    EXPECT_EQ(rows[0].recipe, QStringLiteral("fan"));
    EXPECT_EQ(rows[0].serials, 2);
    EXPECT_EQ(rows[0].firstPass, 1);
    EXPECT_DOUBLE_EQ(rows[0].firstPassYield(), 0.5);
    const YieldRow& pump = rows[1];
    EXPECT_EQ(pump.serials, 4);    // S1, S2, S4, S6: S3 and S5 have no verdict
    EXPECT_EQ(pump.firstPass, 2);  // S1, S4
    EXPECT_EQ(pump.secondPass, 3); // and S2
    EXPECT_EQ(pump.lastPass, 3);   // S6 failed
    EXPECT_EQ(pump.records, 9);
    EXPECT_EQ(pump.verdicts, 5);
    EXPECT_EQ(pump.passed, 3);
    EXPECT_EQ(pump.failed, 2);
    EXPECT_EQ(pump.stationErrors, 2); // aborted and error
    EXPECT_EQ(pump.running, 2);
    EXPECT_EQ(pump.failureReasons.value(QStringLiteral("speed low")), 1);
    EXPECT_EQ(pump.failureReasons.value(QStringLiteral("load high")), 1);
    EXPECT_EQ(pump.failureReasons.size(), 2); // fails only
    EXPECT_EQ(pump.stationReasons.value(QStringLiteral("no drive answers")), 1);
    EXPECT_EQ(pump.stationReasons.value(QStringLiteral("interrupted")), 1);
    EXPECT_EQ(pump.stationReasons.value(QStringLiteral("aborted")), 1);
    EXPECT_EQ(pump.stationReasons.size(), 4);
}

TEST(YieldReportTest, SecondAndLastPassFollowEachSerialsVerdicts)
{
    const QVector<UnitRecord> units{
        unit("A", "pump", at(7), UnitStatus::Fail, "x"),
        unit("A", "pump", at(8), UnitStatus::Fail, "x"),
        unit("A", "pump", at(9), UnitStatus::Pass), // third time: last pass, not second
        unit("B", "pump", at(7), UnitStatus::Pass),
        unit("B", "pump", at(8), UnitStatus::Fail, "y"),
        unit("C", "pump", at(7), UnitStatus::Fail, "x"),
        unit("C", "pump", at(7, 30), UnitStatus::Error),
        unit("C", "pump", at(8), UnitStatus::Pass), // the error between is no attempt
    };
    const auto rows = YieldReport::perRecipe(units);
    ASSERT_EQ(rows.size(), 1);
    EXPECT_EQ(rows[0].serials, 3);
    EXPECT_EQ(rows[0].firstPass, 1);  // B
    EXPECT_EQ(rows[0].secondPass, 2); // B, C
    EXPECT_EQ(rows[0].lastPass, 2);   // A, C: B's latest verdict is a fail
    EXPECT_NEAR(rows[0].secondPassYield(), 2.0 / 3, 1e-12);
    const YieldReport::Earlier before{
        {{QStringLiteral("sha256:pump"), QStringLiteral("A")}, {1, false}}};
    const auto later = YieldReport::perRecipe(units, before);
    EXPECT_EQ(later[0].serials, 2); // A was first tested before: a retest here
}

TEST(YieldReportTest, TwoVersionsOfOneRecipeAreTwoRows)
{
    UnitRecord a = unit("S1", "pump", at(7), UnitStatus::Pass);
    UnitRecord b = unit("S2", "pump", at(8), UnitStatus::Fail, "load high");
    b.recipeChecksum = QStringLiteral("sha256:edited"); // same name and revision, edited by hand
    const auto rows = YieldReport::perRecipe({a, b});
    ASSERT_EQ(rows.size(), 2);
    EXPECT_EQ(rows[0].title(), rows[1].title());
    EXPECT_NE(rows[0].checksum, rows[1].checksum);
    EXPECT_EQ(rows[0].serials + rows[1].serials, 2);
    const YieldRow sum = YieldReport::total(rows);
    EXPECT_EQ(sum.serials, 2);
    EXPECT_EQ(sum.firstPass, 1);
    EXPECT_TRUE(YieldReport::yieldText(sum).contains(QStringLiteral("50.0 %")))
        << qPrintable(YieldReport::yieldText(sum));
}

TEST(YieldReportTest, PerShiftCountsASerialInTheShiftOfItsFirstVerdict)
{
    const QVector<UnitRecord> units{
        unit("S1", "pump", at(7), UnitStatus::Pass),
        unit("S2", "pump", at(13), UnitStatus::Fail, "load high"),
        unit("S2", "pump", at(15), UnitStatus::Pass), // retest in the next shift
        unit("S3", "pump", at(23), UnitStatus::Fail, "alarm"),
        unit("S4", "pump", at(1, 0, 1), UnitStatus::Pass), // after midnight: night shift
    };
    const auto rows = YieldReport::perShift(units, utcShifts());
    ASSERT_EQ(rows.size(), 3);
    EXPECT_EQ(rows[0].shift, QStringLiteral("2026-11-24 06:00"));
    EXPECT_EQ(rows[0].serials, 2);
    EXPECT_EQ(rows[0].firstPass, 1);
    EXPECT_EQ(rows[0].secondPass, 2); // S2 passed at its second verdict, in the next shift
    EXPECT_EQ(rows[0].failureReasons.value(QStringLiteral("load high")), 1);
    EXPECT_EQ(rows[1].shift, QStringLiteral("2026-11-24 14:00"));
    EXPECT_EQ(rows[1].serials, 0);
    EXPECT_EQ(rows[1].records, 1);
    EXPECT_EQ(rows[2].shift, QStringLiteral("2026-11-24 22:00"));
    EXPECT_EQ(rows[2].serials, 2);
    EXPECT_EQ(rows[2].firstPass, 1);
    EXPECT_EQ(rows[2].failureReasons.value(QStringLiteral("alarm")), 1);
    const QByteArray csv = ResultCsv::yield(rows);
    EXPECT_TRUE(csv.contains("pump,A,sha256:pump,2026-11-24 06:00,2,1,0.5,2,1,2,1,2,1,1,0,0,fail,"
                             "load high,1\r\n"))
        << csv.data();
    EXPECT_TRUE(csv.contains("pump,A,sha256:pump,2026-11-24 14:00,0,0,0,0,0,0,0,1,1,0,0,0,,,0\r\n"))
        << csv.data();
}

TEST(YieldReportTest, ARetestOfAUnitFirstTestedBeforeTheRangeIsNoFirstPass)
{
    const QVector<UnitRecord> today{
        unit("S1", "pump", at(7), UnitStatus::Pass),
        unit("S2", "pump", at(8), UnitStatus::Pass), // failed yesterday: a retest
    };
    const YieldReport::Earlier earlier{
        {{QStringLiteral("sha256:pump"), QStringLiteral("S2")}, {1, false}}};
    const auto rows = YieldReport::perRecipe(today, earlier);
    ASSERT_EQ(rows.size(), 1);
    EXPECT_EQ(rows[0].serials, 1);
    EXPECT_EQ(rows[0].firstPass, 1);
    EXPECT_EQ(rows[0].records, 2);
    const auto naive = YieldReport::perRecipe(today);
    EXPECT_EQ(naive[0].serials, 2); // without it, S2's retest would look like a first pass
}
