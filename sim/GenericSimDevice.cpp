#include "sim/GenericSimDevice.h"

namespace opentop {

GenericSimDevice::GenericSimDevice(const Profile& profile, const QString& variant, int slave)
    : SimDevice(profile, variant, slave)
{
}

} // namespace opentop
