#pragma once

#include "model/session/DeviceSession.h"

#include <memory>

namespace opentop {

struct ReadBlockPlan;

// DeviceSession::readMany: several parameters of one drive in as few requests as the device
// allows (ReadPlanner), two blocks queued on the bus at a time, one request per parameter where
// the device refuses a block. Each value read goes into the session's cache.
class BlockReader
{
public:
    static void read(DeviceSession* session, const QStringList& names, DeviceSession::ManyDone done,
                     ModbusRequest::Priority priority);
    // The request that reads one parameter (function 03 or 04, as the profile says).
    static ModbusRequest requestFor(int slave, const ParameterMeta& meta);

private:
    struct State;
    static void next(DeviceSession* session, std::shared_ptr<State> state);
    static void submit(DeviceSession* session, std::shared_ptr<State> state,
                       const ReadBlockPlan& plan);
};

} // namespace opentop
