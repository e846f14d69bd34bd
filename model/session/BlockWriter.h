#pragma once

#include "transport/ModbusRequest.h"

#include <QVector>
#include <functional>

namespace opentop {

class DeviceSession;
struct ParameterMeta;

// The frame that writes a setting: function 06 or 16 at its address, or, for a setting the
// device wants in a larger frame (`writeBlock`: the DC controller's configuration and GPIO
// writes, which also store), the whole block with the rest of it read from the drive first so
// that it keeps its values.
class BlockWriter
{
public:
    // `then` gets the request, or why it could not be built (nothing was written).
    static void frame(DeviceSession* session, const ParameterMeta& meta,
                      const QVector<quint16>& registers,
                      std::function<void(const ModbusRequest& request, const QString& error)> then);
};

} // namespace opentop
