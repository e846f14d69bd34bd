#pragma once

#include "SerialDriver.h"

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

private:
    int m_fd;
    _modbus* m_ctx;
};

} // namespace opentop
