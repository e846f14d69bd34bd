// The status light paints the colour and tells the texts of the profile's status LED table, so
// that changing the table changes the light.
#include "ui/widgets/StatusLight.h"
#include "model/profile/ProfileRegistry.h"

#include <gtest/gtest.h>

namespace opentop {

namespace {

DriveStatus runningCw(const Profile* profile)
{
    DriveStatus s;
    s.polled = s.answered = true;
    s.running = true;
    s.reverse = false;
    DriveStatusPoller::applyLed(&s, profile);
    return s;
}

} // namespace

TEST(StatusLightTest, FollowsTheProfilesLedTable)
{
    const Profile& dbu = *ProfileRegistry::builtIn().family(QStringLiteral("dbu"));
    StatusLight light;
    light.setStatus(runningCw(&dbu));
    EXPECT_EQ(light.led(), DriveStatus::Led::Orange);
    EXPECT_EQ(light.shownColor(), QColor(dbu.ledEntry(QStringLiteral("orange"))->colour));
    EXPECT_TRUE(light.toolTip().contains(dbu.ledEntry(QStringLiteral("orange"))->label))
        << qPrintable(light.toolTip());
    EXPECT_TRUE(light.toolTip().contains(dbu.ledEntry(QStringLiteral("orange"))->meaning))
        << qPrintable(light.toolTip());

    Profile edited = dbu;
    for (StatusLedEntry& e : edited.statusLed) {
        if (e.light == QLatin1String("orange")) {
            e.colour = QStringLiteral("#010203");
            e.label = QStringLiteral("Amber");
            e.meaning = QStringLiteral("Turning clockwise");
        }
    }
    light.setStatus(runningCw(&edited));
    EXPECT_EQ(light.shownColor(), QColor(0x01, 0x02, 0x03));
    EXPECT_TRUE(light.toolTip().startsWith(QStringLiteral("Status light Amber: ")))
        << qPrintable(light.toolTip());
    EXPECT_TRUE(light.toolTip().contains(QStringLiteral("Turning clockwise")));
    EXPECT_EQ(StatusLight::color(runningCw(&edited), DriveStatus::Led::Orange),
              QColor(0x01, 0x02, 0x03));
    // Shown grey (not live): the program's grey, whatever the table says.
    EXPECT_EQ(StatusLight::color(runningCw(&edited), DriveStatus::Led::Grey),
              StatusLight::color(DriveStatus::Led::Grey));

    // A family without the table: the program's own colour.
    light.setStatus(runningCw(ProfileRegistry::builtIn().family(QStringLiteral("dcpid"))));
    EXPECT_EQ(light.shownColor(), StatusLight::color(DriveStatus::Led::Orange));
}

} // namespace opentop
