#pragma once

#include "model/run/GroupFollowers.h"
#include "model/run/RunControl.h"

#include <QLabel>
#include <functional>

namespace opentop {

// What the Test run page read back after a command: the drive's state with the time it was read
// (a snapshot, and it says so: what the drive does now is in the live box), and after a motion
// command what each drive of its communication group does (GroupFollowers).
class CommandReadBack : public QLabel
{
    Q_OBJECT
public:
    explicit CommandReadBack(QWidget* parent = nullptr);

    // After `settleMs`, reads the drive's state and shows it, then what each of `group` (the
    // drives of its communication group, after a motion command; or none) does now; `done`
    // gets whether every one of them runs.
    void readAfter(RunControl* control, DeviceSession* session,
                   const QVector<DeviceSession*>& group, int settleMs,
                   std::function<void(bool allRun)> done);
    void showState(const RunControl::State& state);
    // Adds what each drive of the group does now; returns whether every one of them runs.
    bool showGroup(const QVector<GroupFollowers::Drive>& drives);
};

} // namespace opentop
