#pragma once

#include "transport/LineFormat.h"

#include <QtGlobal>

namespace opentop {

// How long frames take on a real RS-485 line, for simulators on a pty or in process where bytes
// arrive instantly: a reply comes after the request's transmission, the 3.5 character gap, the
// device's turnaround and the reply's own transmission.
class WireTiming
{
public:
    WireTiming(int baud = 19200, char parity = 'N', double turnaroundMs = 2.0, int stopBits = 1);
    // The same line's turnaround at another format (a frame sent in a drive's own format).
    WireTiming at(const LineFormat& format) const;

    int bitsPerChar() const; // start + 8 data + parity + stop bits: 10 for 8N1, 11 for 8E1, 8N2
    double charMs() const;
    double frameMs(int bytes) const;
    double gapMs() const; // 3.5 characters, at least 1.75 ms above 19200 bit/s (Modbus spec)
    // From the end of writing the request to the end of the reply on the wire.
    // turnaroundMs < 0: the line's own.
    double replyDelayMs(int requestBytes, int replyBytes, double turnaroundMs = -1) const;
    // Quiet time after a broadcast before the next request.
    double broadcastDelayMs(int requestBytes) const;

    int baud() const { return m_baud; }
    double turnaroundMs() const { return m_turnaroundMs; }

private:
    int m_baud;
    char m_parity;
    double m_turnaroundMs;
    int m_stopBits;
};

} // namespace opentop
