#pragma once

#include "transport/ConnectionSettings.h"

#include <QString>

namespace opentop {

// Line settings a drive talks at whatever it was configured to: the DC controller in
// potentiometer/analog control mode (its manual, 1.1: fixed 9600 bit/s, 8 data bits, even
// parity, 1 stop bit, slave address 1). A scan that finds nothing offers them: the command line
// names the options to retry with, the program's bus panel a button that rescans with them.
class FixedLineHint
{
public:
    static FixedLineHint dcPotentiometer();

    int baud() const { return m_baud; }
    char parity() const { return m_parity; }
    int stopBits() const { return m_stopBits; }
    int slave() const { return m_slave; }

    // Whether a scan of machine numbers `from`–`to` over `settings` would be worth retrying with
    // these settings: a serial line (or a simulated bus) not already at them, or a range without
    // their address.
    bool worthRetrying(const ConnectionSettings& settings, int from, int to) const;
    // `settings` at these line settings (the port, timeouts and retries kept).
    ConnectionSettings applyTo(ConnectionSettings settings) const;
    // "A DC controller in potentiometer/analog control mode talks only at 9600 bit/s, 8E1,
    // address 1."
    QString explanation() const;
    // The command line options that retry with them: "--baud 9600 --parity E --stop-bits 1
    // scan --from 1 --to 1".
    QString commandLine() const;
    // "9600 8E1, address 1", for a button.
    QString shortText() const;

private:
    int m_baud = 9600;
    char m_parity = 'E';
    int m_stopBits = 1;
    int m_slave = 1;
};

} // namespace opentop
