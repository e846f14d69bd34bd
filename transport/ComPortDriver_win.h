#pragma once

#include "transport/SerialDriver.h"

namespace opentop {

// SerialDriver on a COM port libmodbus has open on Windows (its HANDLE: ComPort::handleOf).
// Windows has no RS-485 mode, RTS switching through libmodbus or low-latency flag to ask for:
// direction control and the USB adapter's latency timer are the adapter's and its driver's
// (docs/hardware.md), so those calls answer ENOTSUP. The character format and rate switch
// through the port's DCB. Every call answers EBADF without a handle.
class ComPortDriver : public SerialDriver
{
public:
    explicit ComPortDriver(void* handle);

    int getRs485(Rs485* state) override;
    int setRs485(Rs485* state) override;
    int useRts(bool highWhileSending, int delayUs, Rts* readBack) override;
    int getLowLatency(bool* on) override;
    int setLowLatency(bool on) override;
    int drainOutput() override;
    int setFormat(const LineFormat& format, LineFormat* readBack) override;

private:
    void* m_handle;
};

} // namespace opentop
