#pragma once

#include <QStringList>

namespace opentop {

class ModbusClient;
class Profile;

// Reads the same parameters again and again through DeviceSession::readMany, one request
// after another, as fast as the stack goes: what the monitor and a backup do per block.
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

    // The parameters of the profile's first read block that holds `registers` registers.
    static QStringList fullBlock(const Profile& profile, int registers, int* address);
    static Result run(ModbusClient* client, const Profile& profile, int slave,
                      const QStringList& names, double seconds);
};

} // namespace opentop
