#pragma once

#include "sim/SimDevice.h"

namespace opentop {

// A device of any profiled family, served from the profile alone: registers with their
// defaults, validation of written values, temporary settings kept until their store command.
class GenericSimDevice : public SimDevice
{
public:
    GenericSimDevice(const Profile& profile, const QString& variant, int slave);
};

} // namespace opentop
