#pragma once

namespace opentop {

// The process's local time zone, read once. Without TZ in the environment glibc looks at
// /etc/localtime again (a stat) for every local-time conversion, and the monitor and the
// traffic log stamp and compare thousands of local times a second: 2,400 stats a second at
// 16 drives × 10 Hz. TZ=":/etc/localtime" names the same zone (Qt reads it as "the system's")
// and lets glibc keep what it read. A zone changed while the program runs shows after a restart.
class LocalTimeZone
{
public:
    // Call first in main(), before any thread starts. Leaves a TZ the user set alone.
    static void readOnce();
};

} // namespace opentop
