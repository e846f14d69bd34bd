#pragma once

#include <QObject>
#include <QVector>

namespace opentop {

class DeviceSession;

// What a frame sent to a drive also reaches: the drives that execute it without replying (the
// DBU's communication groups, TROY manual 11-3). DeviceSession asks it on every write, so that
// each drive a write reaches validates the value before the frame is built and is read back
// after it (ReachedDrives). Whoever knows the bus's groups implements it: BusGroupTracker in the
// program, the command line's context with the drives named by --bus-drives. A QObject, so that
// a session notices when its provider is gone.
class GroupReach : public QObject
{
    Q_OBJECT
public:
    using QObject::QObject;

    // The sessions of the drives that also execute what is sent to `slave` (not `slave`
    // itself), ascending by machine number; empty when none is known.
    virtual QVector<DeviceSession*> reachedBy(int slave) const = 0;
};

} // namespace opentop
