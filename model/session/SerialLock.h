#pragma once

#include "model/profile/Profile.h"
#include "model/profile/ValueContext.h"

#include <QString>

namespace opentop {

// The setting that prohibits configuration over the serial interface (profile role
// "serialLock", the DC controller's 0x008D). Setting it can shut OpenTOP out of configuring the
// drive over the very line it talks on, so the command line refuses it without --yes and the
// program's windows ask first, both with the text below: what it does and how to undo it.
class SerialLock
{
public:
    // Whether writing `raw` to `meta` sets the profile's serial lock (a non-zero value).
    static bool locks(const Profile& profile, const ParameterMeta& meta, qint64 raw);
    // The warning for such a write, naming the setting as `context` names parameters and saying
    // how to undo it; empty when the write does not lock.
    static QString warning(const Profile& profile, const ParameterMeta& meta, qint64 raw,
                           const ValueContext& context = {});
};

} // namespace opentop
