#pragma once

#include "transport/LineFormat.h"

#include <QtGlobal>
#include <cerrno>

namespace opentop {

// The driver calls SerialLineSetup makes on an open serial port, behind an interface so that
// its decisions can be tested with answers no pty gives (a driver that takes RS-485 mode, a
// flag that does not stick). Each call returns 0 or an errno.
class SerialDriver
{
public:
    // struct serial_rs485 without the kernel header: flags are SER_RS485_* (linux/serial.h).
    struct Rs485
    {
        quint32 flags = 0;
        quint32 delayBeforeMs = 0;
        quint32 delayAfterMs = 0;
    };
    // libmodbus' RTS direction control as it stands after asking.
    struct Rts
    {
        bool highWhileSending = true;
        int delayUs = 0; // before and after each request
    };

    virtual ~SerialDriver() = default;

    virtual int getRs485(Rs485* state) = 0; // TIOCGRS485
    // TIOCSRS485; `state` comes back as the driver changed it.
    virtual int setRs485(Rs485* state) = 0;
    // libmodbus raises/drops RTS around each request; 0 keeps libmodbus' delay (one character
    // time). Fails when RTS cannot be switched on this port (TIOCMGET), which libmodbus itself
    // does not notice.
    virtual int useRts(bool highWhileSending, int delayUs, Rts* readBack) = 0;
    virtual int getLowLatency(bool* on) = 0; // TIOCGSERIAL, ASYNC_LOW_LATENCY
    virtual int setLowLatency(bool on) = 0;  // TIOCSSERIAL
    // Waits until everything written has left the UART (tcdrain).
    virtual int drainOutput() { return 0; }
    // The character format and rate (termios, applied once the output has drained); `readBack`
    // as the driver has it afterwards. A pty keeps the rate, stop bits, PARODD and INPCK but
    // drops PARENB and forces 8 data bits: parity shows there as INPCK (see hardware.md).
    virtual int setFormat(const LineFormat& format, LineFormat* readBack)
    {
        Q_UNUSED(format);
        Q_UNUSED(readBack);
        return ENOTSUP;
    }
};

} // namespace opentop
