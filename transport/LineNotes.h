#pragma once

#include <QByteArray>

namespace opentop {

struct ModbusRequest;
struct ModbusResult;

// What LibmodbusBackend learns of the line between transactions and must not forget: what it
// threw away (a whole frame names its sender, anything else was garbled on the line), told with
// the next result; and, after a silent timeout, until when the longest reply to that request
// could still be on the wire. On a half-duplex line a request sent into a reply destroys both,
// and a reply may begin just before the wait ends or reach us only whole (an adapter's latency,
// a gateway): so nothing goes out until then, except a scan's probe after another probe
// (ModbusRequest::probe: the scan sees the collision and asks again). All times on the
// backend's clock, in ms.
class LineNotes
{
public:
    // Discarded bytes: a whole frame with a good CRC at their start names its sender
    // (ModbusResult::lateReplyFrom); bytes without one were garbled (discardedGarbled).
    void noteDiscarded(const QByteArray& rtu);
    // Adds what was noted to `result` (a sender only where it names none yet) and forgets
    // what it added.
    void passOn(ModbusResult* result);

    // `request` timed out silently; a reply to it may be on the wire until `untilMs`.
    void hold(const ModbusRequest& request, double untilMs);
    // Before sending `request` at `nowMs`: how long it must wait for the line (0: at once).
    // The hold is over either way.
    double heldFor(const ModbusRequest& request, double nowMs);
    // The longest RTU frame a device may answer `request` with (an exception is shorter).
    static int longestReplyBytes(const ModbusRequest& request);

    void clear() { *this = LineNotes(); }

private:
    int m_replyFrom = -1;
    bool m_garbled = false;
    double m_heldUntilMs = 0;
    bool m_heldByProbe = false;
};

} // namespace opentop
