#pragma once

#include <QtGlobal>

namespace opentop {

// CPU time and resident memory of a running process, read from /proc.
class ProcessStats
{
public:
    explicit ProcessStats(qint64 pid);

    // User + system CPU time so far, in seconds; < 0 when the process is gone.
    double cpuSeconds() const;
    // Resident set size in MiB; < 0 when the process is gone.
    double rssMiB() const;

private:
    qint64 m_pid;
};

} // namespace opentop
