#pragma once

#include <QString>

namespace opentop {

// The machine the figures were measured on: absolute times vary between machines, so every
// run says where it ran ("Intel(R) Xeon(R) ... , 2 cores, Linux 6.1, Qt 6.4.2, libmodbus 3.1.6").
class MachineInfo
{
public:
    static QString describe();
    static QString cpuModel();
    static int cores();
    // Load average over the last minute: figures on a busy machine are worth less.
    static double loadAverage();
};

} // namespace opentop
