#pragma once

#include "ui/trends/TrendChart.h"

namespace opentop {

class Profile;

// What a drive's trend shows unless the user chooses: current speed, target speed and load
// (the profile's roles); a family without target and load roles (the DC controller) gets its
// other numeric monitor values instead (PWM duty, current), so its chart is not one lone line.
class TrendDefaults
{
public:
    static QVector<TrendSource> forDrive(const Profile& profile, int slave);
};

} // namespace opentop
