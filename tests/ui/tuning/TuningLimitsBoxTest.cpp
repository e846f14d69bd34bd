// The tuning page's limits box on its own: empty fields take the page's defaults (shown as
// "auto: …", a current limit of 0 as "none"); a limit that is not a number above 0 is refused
// naming the unit, and nothing else is taken from it.
#include "ui/tuning/TuningLimitsBox.h"

#include <QLineEdit>

using namespace opentop;

namespace {

QLineEdit* field(TuningLimitsBox& box, const char* name)
{
    return box.findChild<QLineEdit*>(QString::fromLatin1(name));
}

} // namespace

TEST(TuningLimitsBoxTest, EmptyFieldsTakeTheDefaultsAndSaySo)
{
    TuningLimitsBox box;
    box.setSpeedUnit(QStringLiteral("1/s"));
    box.setDefaults(450, 0);
    ASSERT_TRUE(field(box, "maxSpeed") && field(box, "maxCurrent"));
    EXPECT_TRUE(field(box, "maxSpeed")->placeholderText().contains(QStringLiteral("450")));
    EXPECT_EQ(field(box, "maxCurrent")->placeholderText(), QStringLiteral("none"));
    TuningRunner::Limits base;
    base.commLossS = 0.7;
    QString error;
    const auto limits = box.limits(base, &error);
    ASSERT_TRUE(limits) << qPrintable(error);
    EXPECT_EQ(limits->maxSpeed, 450);
    EXPECT_EQ(limits->maxCurrent, 0);  // no current limit
    EXPECT_EQ(limits->commLossS, 0.7); // the rest of the base is kept
}

TEST(TuningLimitsBoxTest, ATypedLimitIsTakenAndOneThatIsNotAboveZeroIsRefused)
{
    TuningLimitsBox box;
    box.setSpeedUnit(QStringLiteral("r/min"));
    box.setDefaults(3000, 4.5);
    QString error;
    field(box, "maxSpeed")->setText(QStringLiteral("2500"));
    field(box, "maxCurrent")->setText(QStringLiteral("3.2"));
    auto limits = box.limits({}, &error);
    ASSERT_TRUE(limits) << qPrintable(error);
    EXPECT_EQ(limits->maxSpeed, 2500);
    EXPECT_EQ(limits->maxCurrent, 3.2);

    for (const char* wrong : {"0", "-5", "fast"}) {
        field(box, "maxSpeed")->setText(QString::fromLatin1(wrong));
        error.clear();
        EXPECT_FALSE(box.limits({}, &error)) << wrong;
        EXPECT_TRUE(error.contains(QStringLiteral("r/min"))) << qPrintable(error);
    }
    field(box, "maxSpeed")->clear();
    field(box, "maxCurrent")->setText(QStringLiteral("0"));
    EXPECT_FALSE(box.limits({}, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("A"))) << qPrintable(error);
}
