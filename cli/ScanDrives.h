#pragma once

#include "model/session/DeviceInfo.h"

#include <QVector>

namespace opentop {

class CliContext;

// What `scan` adds to the drives it found before showing them: the variants the drives do not
// report (--variant, the simulated bus list), a one-model family's own model name, and the
// names users gave the machines of this bus (`name`, or the window's).
class ScanDrives
{
public:
    static void complete(CliContext& context, QVector<DeviceInfo>* devices);
};

} // namespace opentop
