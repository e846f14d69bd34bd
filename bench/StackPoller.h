#pragma once

#include "model/session/ReadPlanner.h"

#include <QStringList>
#include <QVector>

namespace opentop {

class ModbusClient;
class Profile;

// Reads the same parameters again and again through DeviceSession::readMany, as fast as the
// stack goes: what a backup does, drive after drive.
class StackPoller
{
public:
    struct Result
    {
        int transactions = 0;
        int failures = 0;
        double seconds = 0;
        double perSecond() const { return seconds > 0 ? transactions / seconds : 0; }
    };

    // What a backup of a drive of `profile` reads: its settings, and the blocks they take.
    static QStringList backupSettings(const Profile& profile, QVector<ReadBlockPlan>* blocks);
    static Result run(ModbusClient* client, const Profile& profile, int slave,
                      const QStringList& names, double seconds);
};

} // namespace opentop
