#pragma once

#include <QtGlobal>

namespace opentop::soak {

// What the soak measures of a process, read from /proc/PID (Linux): resident memory, open file
// descriptors and threads.
struct ProcessFigures
{
    qint64 rssKb = -1; // VmRSS of /proc/PID/status
    int fds = -1;      // entries of /proc/PID/fd
    int threads = -1;  // Threads of /proc/PID/status
    bool valid() const { return rssKb >= 0 && fds >= 0 && threads >= 0; }
};

class ProcessProbe
{
public:
    // `pid` 0: this process (/proc/self).
    static ProcessFigures read(qint64 pid = 0);
};

} // namespace opentop::soak
