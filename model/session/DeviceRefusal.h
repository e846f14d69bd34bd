#pragma once

#include "model/profile/CodeTable.h"

#include <QObject>
#include <functional>
#include <optional>

namespace opentop {

class ModbusClient;
class Profile;
struct ParameterMeta;
struct ModbusResult;

// Why a drive answered a request with a Modbus exception, in the profile's words: the code a DBU
// leaves in its communication error register (read here), or the entry of the profile's own
// exception table (the DC controller), each with what it means and what to do.
class DeviceRefusal
{
public:
    struct Reason
    {
        std::optional<CodeEntry> entry; // the profile's entry, when the code is known
        QString code;                   // "E2h Cannot execute command"; a DBU's register only
        bool retry = false; // nothing was executed: the same request may be sent again (busy)
    };

    // The reason for `result` (an exception; anything else has none). `context` guards the
    // callback as for ModbusClient::submit.
    static void read(ModbusClient* client, QObject* context, const Profile& profile, int slave,
                     const ModbusResult& result, std::function<void(const Reason&)> done);
    // The profile's readable communication error register (code table "comm_error"), or nullptr.
    static const ParameterMeta* errorRegister(const Profile& profile);
    // The entry for a Modbus exception code in a table whose entries name one ("exception"), or
    // nullptr. A DBU's exception 04h has four register codes: none of them is chosen here.
    static const CodeEntry* exceptionEntry(const Profile& profile, int exceptionCode);
};

} // namespace opentop
