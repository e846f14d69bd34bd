// The running data of a drive family and the manual's deceleration advice.
#include "model/profile/RunningData.h"

#include "model/profile/ProfileRegistry.h"

#include <QHash>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

const Profile& dbu()
{
    return *ProfileRegistry::builtIn().forDeviceType(QStringLiteral("dbu200"));
}

ValueContext values(const QHash<QString, qint64>& raw)
{
    ValueContext c;
    c.parameterRaw = [raw](const QString& name) -> std::optional<qint64> {
        return raw.contains(name) ? std::optional(raw.value(name)) : std::nullopt;
    };
    return c;
}

} // namespace

TEST(RunningDataTest, NamesTheParametersOfEachSpno)
{
    EXPECT_EQ(RunningData::count(dbu()), 8);
    EXPECT_EQ(RunningData::parameter(dbu(), 3, QStringLiteral("decel")),
              QStringLiteral("spno3.decel"));
    EXPECT_TRUE(RunningData::parameter(dbu(), 1, QStringLiteral("decel")).isEmpty());
    QString field;
    EXPECT_EQ(RunningData::spnoOf(QStringLiteral("spno7.speed"), &field), 7);
    EXPECT_EQ(field, QStringLiteral("speed"));
    EXPECT_EQ(RunningData::spnoOf(QStringLiteral("core.upper_limit")), 0);
}

TEST(RunningDataTest, WarnsOfADecelerationBelowTwoSecondsFromHighSpeedOnly)
{
    EXPECT_FALSE(RunningData::decelerationWarning(2, 1500, 0.5).isEmpty());
    EXPECT_TRUE(RunningData::decelerationWarning(2, 1000, 0.5).isEmpty()); // not high speed
    EXPECT_TRUE(RunningData::decelerationWarning(2, 3000, 2.0).isEmpty()); // 2 s is enough
    EXPECT_TRUE(RunningData::decelerationWarning(2, std::nullopt, 0.5).isEmpty());
    // Raw values through the profile's scale: a deceleration written as 0.5 s (raw 5) for a
    // speed of 2500 r/min on the drive, and the same speed written with 3.0 s on the drive.
    const ValueContext onDrive =
        values({{QStringLiteral("spno4.speed"), 2500}, {QStringLiteral("spno4.decel"), 30}});
    EXPECT_TRUE(RunningData::warningFor(dbu(), QStringLiteral("spno4.decel"), 5, onDrive)
                    .startsWith(QStringLiteral("SPno4")));
    EXPECT_TRUE(
        RunningData::warningFor(dbu(), QStringLiteral("spno4.speed"), 2500, onDrive).isEmpty());
    EXPECT_TRUE(
        RunningData::warningFor(dbu(), QStringLiteral("core.upper_limit"), 1, onDrive).isEmpty());
    const QStringList all =
        RunningData::warnings(dbu(), values({{QStringLiteral("spno2.speed"), 3000},
                                             {QStringLiteral("spno2.decel"), 5},
                                             {QStringLiteral("spno5.speed"), 800},
                                             {QStringLiteral("spno5.decel"), 5}}));
    ASSERT_EQ(all.size(), 1);
    EXPECT_TRUE(all.first().contains(QStringLiteral("3000 r/min")));
}

TEST(RunningData, TheSummaryNamesEverySpnoWithAShortDecelerationFromHighSpeedInOneSentence)
{
    const QString one = RunningData::summary(
        dbu(), values({{QStringLiteral("spno2.speed"), 3000}, {QStringLiteral("spno2.decel"), 5}}));
    EXPECT_TRUE(one.contains(QStringLiteral("on SPno2 ("))) << qPrintable(one);
    EXPECT_TRUE(one.contains(QStringLiteral("3000 r/min in 0.5 s"))) << qPrintable(one);
    const QString several =
        RunningData::summary(dbu(), values({{QStringLiteral("spno2.speed"), 3000},
                                            {QStringLiteral("spno2.decel"), 5},
                                            {QStringLiteral("spno4.speed"), 1700},
                                            {QStringLiteral("spno4.decel"), 10},
                                            {QStringLiteral("spno5.speed"), 800},
                                            {QStringLiteral("spno5.decel"), 5}}));
    EXPECT_TRUE(several.contains(QStringLiteral("on SPno2, SPno4 ("))) << qPrintable(several);
    EXPECT_TRUE(several.contains(QString::fromUtf8("1700–3000 r/min in 0.5–1.0 s")))
        << qPrintable(several);
    EXPECT_FALSE(several.contains(QStringLiteral("SPno5")));
    EXPECT_EQ(several.count(QStringLiteral("manual")), 1);
    EXPECT_TRUE(RunningData::summary(dbu(), values({{QStringLiteral("spno2.speed"), 3000},
                                                    {QStringLiteral("spno2.decel"), 20}}))
                    .isEmpty());
}

// Issue 24: what the drive runs is read from its status (the "selected" role), not assumed.
TEST(RunningDataTest, TheRunningDataTheDriveRunsComesFromItsStatusBits)
{
    // status.driver bits 8–10 hold the selected running data (code N-1).
    auto raw = [](double value) {
        return [value](const QString& name) -> std::optional<double> {
            return name == QLatin1String("status.driver") ? std::optional(value) : std::nullopt;
        };
    };
    EXPECT_EQ(RunningData::selected(dbu(), raw(3 << 8)), 4);
    EXPECT_EQ(RunningData::selected(dbu(), raw((7 << 8) | 0x2)), 8); // running bits beside it
    EXPECT_EQ(RunningData::selected(dbu(), raw(0)), 1);
    EXPECT_FALSE(RunningData::selected(dbu(), [](const QString&) { return std::nullopt; }));
    // A family without running data tells none.
    EXPECT_FALSE(RunningData::selected(*ProfileRegistry::builtIn().family(QStringLiteral("dcpid")),
                                       raw(3 << 8)));
}
