#pragma once

#include "transport/SerialDriver.h"

struct _modbus; // libmodbus' modbus_t, kept out of this header

namespace opentop {

// SerialDriver on a port libmodbus has open: ioctls on its descriptor, RTS through the context.
class IoctlSerialDriver : public SerialDriver
{
public:
    IoctlSerialDriver(int fd, _modbus* ctx);

    int getRs485(Rs485* state) override;
    int setRs485(Rs485* state) override;
    int useRts(bool highWhileSending, int delayUs, Rts* readBack) override;
    int getLowLatency(bool* on) override;
    int setLowLatency(bool on) override;
    int drainOutput() override;
    int setFormat(const LineFormat& format, LineFormat* readBack) override;
    // The format a termios describes (parity from PARENB, or from INPCK where a pty dropped
    // PARENB); baud 0 for a rate outside the standard ones. Also for the simulator, which reads
    // a pty master's termios (TCGETS on a master returns its slave's).
    static LineFormat formatOf(int fd);

private:
    int m_fd;
    _modbus* m_ctx;
};

} // namespace opentop
