#pragma once

#include "transport/ConnectionSettings.h"
#include "transport/SerialDriver.h"
#include "transport/SerialLineReport.h"

#include <optional>

namespace opentop {

class SerialSysfs;

// Sets a serial port's RS-485 direction control and low-latency mode as the settings ask and
// reports what the driver accepted, read back. Kernel: the driver's RS-485 mode (TIOCSRS485).
// Rts: libmodbus raises and drops RTS around each request (modbus_rtu_set_rts; not
// modbus_rtu_set_serial_mode, which is TIOCSRS485 again). Auto: kernel where the driver takes
// it, else RTS. Off leaves the driver's RS-485 state alone (and reports it when it is on).
// Applied by RtuBackend right after opening; restore() puts back what was changed, so the next
// program finds the port as we did.
class SerialLineSetup
{
public:
    SerialLineReport apply(SerialDriver& driver, const ConnectionSettings& settings,
                           const SerialSysfs& sysfs);
    void restore(SerialDriver& driver);
    // Switches the open port to `format` once what was written has left the UART (tcdrain):
    // 0 or an errno, *error saying what failed. The rate must read back as asked (a pty drops
    // parity, see SerialDriver::setFormat, so the rest is not compared). Counts the switches
    // and the time they took (switchCount(), switchMicros()).
    int switchFormat(SerialDriver& driver, const LineFormat& format, QString* error);
    int switchCount() const { return m_switches; }
    qint64 switchMicros() const { return m_switchMicros; }

private:
    void applyDirection(SerialDriver& driver, const ConnectionSettings& settings,
                        SerialLineReport* report);
    bool tryKernel(SerialDriver& driver, const ConnectionSettings& settings,
                   SerialLineReport* report);
    bool tryRts(SerialDriver& driver, const ConnectionSettings& settings, SerialLineReport* report);
    void applyLowLatency(SerialDriver& driver, const ConnectionSettings& settings,
                         const SerialSysfs& sysfs, SerialLineReport* report);

    std::optional<SerialDriver::Rs485> m_savedRs485; // as found, when we changed it
    std::optional<bool> m_savedLowLatency;
    int m_switches = 0;
    qint64 m_switchMicros = 0;
};

} // namespace opentop
