#pragma once

#include <QString>
#include <QVector>

class QWidget;

namespace opentop {

class BusGroupTracker;
class DeviceSession;

// Before a write or command goes to a communication group's parent: the question that names
// the drives it also reaches (they execute it without replying). Every GUI path that writes to
// a drive asks through here; nothing is asked when no other drive is reached.
class GroupWriteCheck
{
public:
    // The sentence naming what a frame to `slave` also reaches; empty when nothing else.
    // (BusGroups::alsoReachesText on the bus `session` belongs to.)
    static QString reachText(const DeviceSession* session);
    static QString reachText(const BusGroupTracker* tracker, int slave);

    // Asks whether `what` (e.g. "Write 2 values to machine number 1") may be sent to the
    // drive(s) when it reaches others; true when nothing else is reached or the user agreed.
    // Nothing is sent here. The default answer is Cancel.
    static bool confirm(QWidget* parent, const DeviceSession* session, const QString& what);
    static bool confirm(QWidget* parent, const BusGroupTracker* tracker, const QVector<int>& slaves,
                        const QString& what);
};

} // namespace opentop
