#pragma once

#include <QCoreApplication>
#include <QStringList>

namespace opentop {

class SimDevice;
struct SimControlResult;

// The console's raw register access to one device: "get ADDR [fc]" and "set ADDR VALUE [fc]",
// without any validation (fc 3 holding, 4 input, 6 the last value of a write-only command).
// Registers the simulation computes are recomputed at the next step.
class SimBackdoor
{
    Q_DECLARE_TR_FUNCTIONS(opentop::SimBackdoor)
public:
    explicit SimBackdoor(SimDevice* device);

    // args: "get" ADDR [fc] or "set" ADDR VALUE [fc].
    SimControlResult getSet(const QStringList& args);

private:
    SimDevice* m_device;
};

} // namespace opentop
