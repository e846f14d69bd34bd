#pragma once

#include "model/session/DeviceInfo.h"

#include <QVector>

namespace opentop {

class CliContext;

// `scan`'s drives of another line format than the port's: with --try-formats, a pass per
// format a profiled drive can be set to (LineFormatHint::otherFormats) over the machine numbers
// not found yet, each drive found getting its format for the rest of the command; without it,
// a hint naming the families a scan at the port's format cannot hear and what a pass would cost.
class ScanFormats
{
public:
    // Runs the passes over `from`–`to`; adds what they find to `devices` (in machine number
    // order). False when interrupted. `elapsedMs` gets the passes' time added.
    static bool run(CliContext& context, int from, int to, int waitMs, QVector<DeviceInfo>* devices,
                    double* elapsedMs);
    // The hint after a scan at the port's format only; nothing when nothing can be missed.
    static void hint(CliContext& context, int from, int to, const QVector<DeviceInfo>& devices);
};

} // namespace opentop
