// GoldenLimits: the hold limits of a recipe tightened around a golden unit's measured values
// by the stated margin (25 % of the value, at least 5 % of full scale), rounded outwards, never
// wider than the default; refused when the golden unit did not pass or a value is missing.
#include "model/eol/GoldenLimits.h"
#include "model/profile/ProfileRegistry.h"
#include "tests/model/eol/RecipeTestSupport.h"

#include <QTimeZone>
#include <cmath>

using namespace opentop;
using namespace opentop::test;

namespace {

QString quantityOf(const QString& family, const QString& parameter, const char* statistic)
{
    const Profile* profile = ProfileRegistry::builtIn().family(family);
    const ParameterMeta* meta = profile ? profile->parameter(parameter) : nullptr;
    return meta ? QStringLiteral("%1 %2").arg(meta->canonicalLabel, QLatin1String(statistic))
                : QString();
}

Measurement measured(int machineNumber, const QString& quantity, double value)
{
    Measurement m;
    m.machineNumber = machineNumber;
    m.step = QStringLiteral("step 5 (hold)");
    m.quantity = quantity;
    m.value = value;
    m.pass = true;
    return m;
}

// What the DBU200 example's golden unit measured: speed around 1500 r/min, the given load.
UnitRecord dbuGolden(double load)
{
    UnitRecord r;
    r.status = UnitStatus::Pass;
    r.started = QDateTime(QDate(2026, 11, 29), QTime(8, 0), QTimeZone::utc());
    const QString dbu = QStringLiteral("dbu");
    const QString speed = QStringLiteral("status.current_speed");
    r.measurements << measured(1, QStringLiteral("time to reach speed"), 1.2)
                   << measured(1, quantityOf(dbu, speed, "min"), 1490)
                   << measured(1, quantityOf(dbu, speed, "mean"), 1500)
                   << measured(1, quantityOf(dbu, speed, "max"), 1511)
                   << measured(1, quantityOf(dbu, QStringLiteral("status.load"), "max"), load);
    return r;
}

const RecipeLimit& holdLimit(const Recipe& recipe, const char* parameter, const char* statistic)
{
    for (const RecipeStep& s : recipe.positions.at(0).steps)
        for (const RecipeLimit& l : s.limits)
            if (l.parameter == QLatin1String(parameter) && l.statistic == QLatin1String(statistic))
                return l;
    static const RecipeLimit none;
    return none;
}

GoldenLimits::Margin standard()
{
    return GoldenLimits::Margin();
}

} // namespace

TEST(GoldenLimitsTest, TheLoadLimitFollowsTheGoldenUnitAndTheSpeedKeepsItsTolerance)
{
    const Recipe recipe = exampleRecipe("recipe-dbu200.json");
    ASSERT_EQ(*holdLimit(recipe, "status.load", "max").upper, 80);
    QString error;
    const auto result =
        GoldenLimits(ProfileRegistry::builtIn()).derive(recipe, dbuGolden(30), standard(), &error);
    ASSERT_TRUE(result) << qPrintable(error);
    // 30 % measured: 25 % of it is 7.5, less than 5 % of the 0–200 % full scale (10): 40 %.
    EXPECT_EQ(holdLimit(result->recipe, "status.load", "max").upper, 40.0);
    EXPECT_FALSE(holdLimit(result->recipe, "status.load", "max").lower);
    // The speed's limits come from its target; 25 % around 1500 r/min would be wider.
    EXPECT_EQ(holdLimit(result->recipe, "status.current_speed", "min").lower, 1450.0);
    EXPECT_EQ(holdLimit(result->recipe, "status.current_speed", "mean").lower, 1475.0);
    EXPECT_EQ(holdLimit(result->recipe, "status.current_speed", "mean").upper, 1525.0);
    EXPECT_EQ(holdLimit(result->recipe, "status.current_speed", "max").upper, 1550.0);
    ASSERT_EQ(result->changes.size(), 4);
    int changed = 0;
    for (const GoldenLimits::Change& c : result->changes)
        changed += c.changed() ? 1 : 0;
    EXPECT_EQ(changed, 1);
    const GoldenLimits::Change& load = result->changes.last();
    EXPECT_EQ(load.measured, 30);
    EXPECT_EQ(
        GoldenLimits::changeText(load).toStdString(),
        quantityOf(QStringLiteral("dbu"), QStringLiteral("status.load"), "max").toStdString() +
            " ≤ 40 % (default ≤ 80 %, measured 30.0 %)");
    // Nothing else of the recipe changes.
    EXPECT_EQ(result->recipe.positions.at(0).settings.size(),
              recipe.positions.at(0).settings.size());
    Recipe back = result->recipe;
    back.positions[0].steps = recipe.positions[0].steps;
    EXPECT_EQ(RecipeFile::checksumOf(back), RecipeFile::checksumOf(recipe));
}

TEST(GoldenLimitsTest, AHighLoadTakesTheRelativeMarginAndNeverWidensTheDefault)
{
    const Recipe recipe = exampleRecipe("recipe-dbu200.json");
    QString error;
    GoldenLimits limits(ProfileRegistry::builtIn());
    // 60 %: 25 % of it is 15, more than 10: 75 %.
    auto result = limits.derive(recipe, dbuGolden(60), standard(), &error);
    ASSERT_TRUE(result) << qPrintable(error);
    EXPECT_EQ(holdLimit(result->recipe, "status.load", "max").upper, 75.0);
    // 70 %: 87.5 % would be wider than the default 80 %, which stays.
    result = limits.derive(recipe, dbuGolden(70), standard(), &error);
    ASSERT_TRUE(result) << qPrintable(error);
    EXPECT_EQ(holdLimit(result->recipe, "status.load", "max").upper, 80.0);
    EXPECT_FALSE(result->changes.last().changed());
    // A 10 % margin, rounded outwards to the parameter's resolution (whole %):
    // 31.1 + max(3.11, 10) = 41.1, rounded up to 42.
    GoldenLimits::Margin narrow;
    narrow.relative = 0.10;
    result = limits.derive(recipe, dbuGolden(31.1), narrow, &error);
    ASSERT_TRUE(result) << qPrintable(error);
    EXPECT_EQ(holdLimit(result->recipe, "status.load", "max").upper, 42.0);
}

TEST(GoldenLimitsTest, AGoldenUnitThatFailedOrWasNotMeasuredGivesNoLimits)
{
    const Recipe recipe = exampleRecipe("recipe-dbu200.json");
    GoldenLimits limits(ProfileRegistry::builtIn());
    QString error;
    UnitRecord failed = dbuGolden(30);
    failed.status = UnitStatus::Fail;
    failed.failureReason = QStringLiteral("step 5 (hold): Load rate max 95 %, allowed ≤ 80 %");
    EXPECT_FALSE(limits.derive(recipe, failed, standard(), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("did not pass"))) << qPrintable(error);
    EXPECT_TRUE(error.contains(failed.failureReason)) << qPrintable(error);

    UnitRecord partial = dbuGolden(30);
    partial.measurements.removeLast(); // no load
    EXPECT_FALSE(limits.derive(recipe, partial, standard(), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("was not measured"))) << qPrintable(error);
    EXPECT_TRUE(error.contains(QStringLiteral("machine number 1"))) << qPrintable(error);

    UnitRecord otherDrive = dbuGolden(30);
    for (Measurement& m : otherDrive.measurements)
        m.machineNumber = 2; // measured on another drive: not this position's
    EXPECT_FALSE(limits.derive(recipe, otherDrive, standard(), &error));
}

TEST(GoldenLimitsTest, TheDcControllersCurrentAndDutyComeDownToWhatItDrew)
{
    const Recipe recipe = exampleRecipe("recipe-dcpid.json");
    const QString dc = QStringLiteral("dcpid");
    const QString f = QStringLiteral("status.commutation");
    UnitRecord r;
    r.status = UnitStatus::Pass;
    r.measurements << measured(7, quantityOf(dc, f, "min"), 296)
                   << measured(7, quantityOf(dc, f, "mean"), 300)
                   << measured(7, quantityOf(dc, f, "max"), 304)
                   << measured(7, quantityOf(dc, QStringLiteral("status.current"), "max"), 0.84)
                   << measured(7, quantityOf(dc, QStringLiteral("status.pwm"), "max"), 41.3);
    QString error;
    const auto result =
        GoldenLimits(ProfileRegistry::builtIn()).derive(recipe, r, standard(), &error);
    ASSERT_TRUE(result) << qPrintable(error);
    const double current = *holdLimit(result->recipe, "status.current", "max").upper;
    EXPECT_GE(current, 0.84 * 1.25);
    EXPECT_LT(current, 3.0);
    EXPECT_DOUBLE_EQ(current, std::round(current * 100) / 100); // the current's 0.01 A
    // PWM 41.3 %: 25 % is 10.3 more than 5 % of its 0–100 % full scale: 51.7 %, at 0.1 %.
    EXPECT_DOUBLE_EQ(*holdLimit(result->recipe, "status.pwm", "max").upper, 51.7);
}
