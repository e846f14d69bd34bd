#pragma once

#include "model/profile/ParamValue.h"

#include <QString>

namespace opentop {

// One drive a write reached besides its target (a communication group child), read back after
// the write (ReachedDrives::verify).
struct ReachedResult
{
    int slave = 0;
    ParamValue value;      // what the drive holds, read back (valid when it was read)
    QString held;          // the same with its unit: "2150 r/min"
    bool verified = false; // read back and equal to what was written
    bool mismatch = false; // read back and different
    QString text;          // for people, naming the drive: what it holds, or why not read
};

} // namespace opentop
