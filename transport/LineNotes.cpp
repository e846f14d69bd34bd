#include "transport/LineNotes.h"

#include "transport/ModbusCrc.h"
#include "transport/ModbusRequest.h"
#include "transport/ModbusResult.h"

#include <modbus.h>
#include <utility>

namespace opentop {

void LineNotes::noteDiscarded(const QByteArray& rtu)
{
    // The shortest reply is an exception: id, function, code, CRC.
    for (int length = 5; length <= rtu.size() && length <= 256; ++length) {
        if (ModbusCrc::check(rtu.left(length))) {
            m_replyFrom = quint8(rtu.at(0));
            return;
        }
    }
    if (!rtu.isEmpty())
        m_garbled = true;
}

void LineNotes::passOn(ModbusResult* result)
{
    if (result->lateReplyFrom < 0)
        result->lateReplyFrom = std::exchange(m_replyFrom, -1);
    result->discardedGarbled |= std::exchange(m_garbled, false);
}

void LineNotes::hold(const ModbusRequest& request, double untilMs)
{
    m_heldUntilMs = untilMs;
    m_heldByProbe = request.probe;
}

double LineNotes::heldFor(const ModbusRequest& request, double nowMs)
{
    const bool probeAfterProbe = request.probe && m_heldByProbe;
    const double leftMs = std::exchange(m_heldUntilMs, 0) - nowMs;
    return probeAfterProbe || leftMs <= 0 ? 0 : leftMs;
}

int LineNotes::longestReplyBytes(const ModbusRequest& request)
{
    if (request.raw)
        return MODBUS_RTU_MAX_ADU_LENGTH; // its length is the device's choice
    if (request.isRead())
        return 5 + 2 * request.count; // id, function, byte count, registers, CRC
    return 8;                         // a write's echo
}

} // namespace opentop
