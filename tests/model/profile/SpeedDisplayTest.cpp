// What the drive's speed display shows: formulas of docs/speed-display.md against values worked
// out by hand.
#include "model/profile/SpeedDisplay.h"
#include "model/profile/ProfileRegistry.h"

#include <QHash>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

SpeedDisplay::Settings settings(SpeedDisplay::Mode mode, double reduction = 1, double increase = 1,
                                int decimals = 3)
{
    SpeedDisplay::Settings s;
    s.mode = mode;
    s.reduction = reduction;
    s.increase = increase;
    s.decimals = decimals;
    return s;
}

} // namespace

TEST(SpeedDisplay, RpmIsTheShaftSpeedBehindTheRatios)
{
    SpeedDisplay plain(settings(SpeedDisplay::Mode::Rpm));
    SpeedDisplay::Shown shown = plain.show(1500);
    EXPECT_TRUE(shown.valid);
    EXPECT_DOUBLE_EQ(shown.value, 1500);
    EXPECT_EQ(shown.text, QStringLiteral("1500.000")); // 3 decimals, the factory setting
    EXPECT_EQ(shown.unit, QStringLiteral("r/min"));

    // 1500 / 7.5 = 200 r/min at the gearbox output.
    SpeedDisplay geared(settings(SpeedDisplay::Mode::Rpm, 7.5, 1, 1));
    EXPECT_EQ(geared.show(1500).text, QStringLiteral("200.0"));
    // 3000 / 10 × 2.5 = 750.
    SpeedDisplay both(settings(SpeedDisplay::Mode::Rpm, 10, 2.5, 0));
    EXPECT_EQ(both.show(3000).text, QStringLiteral("750"));
    // Reversing shows "-" before the speed.
    EXPECT_EQ(both.show(-3000).text, QStringLiteral("-750"));
    EXPECT_EQ(both.show(0).text, QStringLiteral("0"));
}

TEST(SpeedDisplay, CorrectionsApplyBySpeedSection)
{
    SpeedDisplay::Settings s = settings(SpeedDisplay::Mode::Rpm, 1, 1, 0);
    s.corrections[0] = 5;
    s.corrections[1] = -3;
    s.corrections[2] = 10;
    s.corrections[3] = -20;
    const SpeedDisplay d(s);
    const QHash<int, double> expected{{300, 305},   {500, 505},    {501, 498},   {1000, 997},
                                      {1001, 1011}, {2000, 2010},  {2001, 1981}, {3000, 2980},
                                      {0, 0},       {-1500, -1510}};
    for (auto it = expected.cbegin(); it != expected.cend(); ++it)
        EXPECT_DOUBLE_EQ(d.correctedMotorRpm(it.key()), it.value()) << it.key();
    EXPECT_EQ(SpeedDisplay::section(0), -1);
    EXPECT_EQ(SpeedDisplay::section(250), 0);
    EXPECT_EQ(SpeedDisplay::section(2500), 3);

    // A negative correction never turns the speed around.
    s.corrections[0] = -100;
    EXPECT_DOUBLE_EQ(SpeedDisplay(s).correctedMotorRpm(50), 0);
    EXPECT_DOUBLE_EQ(SpeedDisplay(s).correctedMotorRpm(-50), 0);
    // The correction is in motor r/min, before the ratios: (1000 - 3) / 2 = 498.5.
    s.corrections[1] = -3;
    s.reduction = 2;
    s.decimals = 1;
    EXPECT_EQ(SpeedDisplay(s).show(1000).text, QStringLiteral("498.5"));
}

TEST(SpeedDisplay, LinearSpeedIsShaftSpeedTimesCircumference)
{
    // 1500 / 5 = 300 r/min; 300 × π × 100 mm = 94.2478 m/min.
    SpeedDisplay::Settings m = settings(SpeedDisplay::Mode::LinearMeter, 5, 1, 2);
    m.diameterMeter = 100;
    const SpeedDisplay::Shown meters = SpeedDisplay(m).show(1500);
    EXPECT_NEAR(meters.value, 94.2477796, 1e-6);
    EXPECT_EQ(meters.text, QStringLiteral("94.25"));
    EXPECT_EQ(meters.unit, QStringLiteral("m/min"));

    // 250 × 2 = 500 r/min; 500 × π × 457.2 mm (0.5 yd) = 785.398 yd/min.
    SpeedDisplay::Settings yd = settings(SpeedDisplay::Mode::LinearYard, 1, 2, 0);
    yd.diameterYard = 457.2;
    const SpeedDisplay::Shown yards = SpeedDisplay(yd).show(250);
    EXPECT_EQ(yards.text, QStringLiteral("785"));
    EXPECT_EQ(yards.unit, QStringLiteral("yd/min"));
    // A diameter of 0 shows 0.
    yd.diameterYard = 0;
    EXPECT_EQ(SpeedDisplay(yd).show(250).text, QStringLiteral("0"));
}

TEST(SpeedDisplay, TimeIsDistanceOverLinearSpeed)
{
    // 1000 / 10 = 100 r/min; 100 × π × 200 mm = 62.832 m/min; 100 m take 1.5915 min = 95.49 s.
    SpeedDisplay::Settings s = settings(SpeedDisplay::Mode::Time, 10, 1, 1);
    s.timeDiameter = 200;
    s.distance = 100;
    const SpeedDisplay::Shown minSec = SpeedDisplay(s).show(1000);
    EXPECT_TRUE(minSec.valid);
    EXPECT_NEAR(minSec.value, 1.591549, 1e-6);
    EXPECT_EQ(minSec.text, QStringLiteral("1:35"));
    EXPECT_EQ(minSec.unit, QStringLiteral("min:s"));
    // Direction does not matter for a time.
    EXPECT_EQ(SpeedDisplay(s).show(-1000).text, QStringLiteral("1:35"));

    s.timeInSeconds = true;
    const SpeedDisplay::Shown seconds = SpeedDisplay(s).show(1000);
    EXPECT_EQ(seconds.text, QStringLiteral("95.5"));
    EXPECT_EQ(seconds.unit, QStringLiteral("s"));

    // Standing still the time is endless.
    s.timeInSeconds = false;
    const SpeedDisplay::Shown still = SpeedDisplay(s).show(0);
    EXPECT_FALSE(still.valid);
    EXPECT_EQ(still.text, QStringLiteral("--:--"));
}

TEST(SpeedDisplay, BuiltFromTheParametersItIsGiven)
{
    const SpeedDisplay::Names names = SpeedDisplay::Names::withPrefix();
    QHash<QString, double> values{{names.mode, 2},
                                  {names.reduction, 5},
                                  {names.increase, 1},
                                  {names.decimals, 2},
                                  {names.diameterMeter, 100}};
    for (const QString& c : names.corrections)
        values.insert(c, 0);
    auto lookup = [&values](const QString& n) {
        return values.contains(n) ? std::optional<double>(values.value(n)) : std::nullopt;
    };
    QString error;
    const std::optional<SpeedDisplay> d = SpeedDisplay::fromValues(names, lookup, &error);
    ASSERT_TRUE(d) << qPrintable(error);
    EXPECT_EQ(d->show(1500).text, QStringLiteral("94.25"));

    // The yard diameter is not needed in meters; a missing meter diameter is named.
    values.remove(names.diameterMeter);
    EXPECT_FALSE(SpeedDisplay::fromValues(names, lookup, &error));
    EXPECT_TRUE(error.contains(names.diameterMeter)) << qPrintable(error);
    values.insert(names.diameterMeter, 100);
    values.insert(names.mode, 7);
    EXPECT_FALSE(SpeedDisplay::fromValues(names, lookup, &error));
    values.insert(names.mode, 0);
    values.insert(names.reduction, 0);
    EXPECT_FALSE(SpeedDisplay::fromValues(names, lookup, &error));

    // Other names: a profile with its settings elsewhere.
    SpeedDisplay::Names other = SpeedDisplay::Names::withPrefix(QStringLiteral("display."));
    EXPECT_EQ(other.mode, QStringLiteral("display.mode"));
    EXPECT_EQ(other.corrections.value(3), QStringLiteral("display.ro3"));

    const ProfileRegistry& registry = ProfileRegistry::builtIn();
    EXPECT_TRUE(SpeedDisplay::supported(*registry.family(QStringLiteral("dbu"))));
    EXPECT_FALSE(SpeedDisplay::supported(*registry.family(QStringLiteral("dcpid"))));
}

TEST(SpeedDisplay, RollerDiametersAreInMillimetres)
{
    // A 50 mm roller behind no gear at 1500 r/min: 1500 × π × 0.05 m = 235.619 m/min.
    SpeedDisplay::Settings m = settings(SpeedDisplay::Mode::LinearMeter, 1, 1, 3);
    m.diameterMeter = 50;
    EXPECT_NEAR(SpeedDisplay(m).show(1500).value, 235.6194, 1e-4);
    // 100 mm: 471.239 m/min, a plausible belt speed (not 471,238.898 as if it were metres).
    m.diameterMeter = 100;
    EXPECT_NEAR(SpeedDisplay(m).show(1500).value, 471.2389, 1e-4);
    // The same roller in yd/min: 471.239 m/min ÷ 0.9144 m/yd = 515.353 yd/min.
    SpeedDisplay::Settings yd = settings(SpeedDisplay::Mode::LinearYard, 1, 1, 3);
    yd.diameterYard = 100;
    EXPECT_NEAR(SpeedDisplay(yd).show(1500).value, 515.3532, 1e-4);
    // Time over 100 yd with a 100 mm roller at 150 r/min: 150 × π × 0.1 / 0.9144 = 51.535
    // yd/min, so 1.9404 min = 1:56.
    SpeedDisplay::Settings t = settings(SpeedDisplay::Mode::Time, 10, 1, 1);
    t.timeDiameter = 100;
    t.distance = 100;
    t.distanceInYards = true;
    EXPECT_EQ(SpeedDisplay(t).show(1500).text, QStringLiteral("1:56"));
}

TEST(SpeedDisplay, ThePanelShowsFiveDigits)
{
    // 1350 r/min with 3 decimals: computed 1350.000, the panel shows 1350.0 (the point takes
    // no digit), as the monitor's panel mirror does.
    SpeedDisplay::Settings s = settings(SpeedDisplay::Mode::Rpm, 1, 1, 3);
    const SpeedDisplay::Shown shown = SpeedDisplay(s).show(1350);
    EXPECT_EQ(shown.text, QStringLiteral("1350.000"));
    EXPECT_EQ(shown.panel, QStringLiteral("1350.0"));
    EXPECT_FALSE(shown.overflow);
    // The minus takes a digit.
    EXPECT_EQ(SpeedDisplay(s).show(-1350).panel, QStringLiteral("-1350"));
    // What does not fit even without decimals is shown whole and marked.
    s.increase = 24;
    s.decimals = 0;
    const SpeedDisplay::Shown big = SpeedDisplay(s).show(3000);
    EXPECT_EQ(big.panel, QStringLiteral("72000"));
    EXPECT_FALSE(big.overflow);
    EXPECT_TRUE(SpeedDisplay(s).show(-3000).overflow); // -72000: six characters
    bool overflow = false;
    EXPECT_EQ(SpeedDisplay::panelText(QStringLiteral("471.239"), &overflow),
              QStringLiteral("471.23"));
    EXPECT_FALSE(overflow);
}
