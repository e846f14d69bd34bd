#pragma once

#include <QString>

namespace opentop {

// How to reach a bus. Exactly one kind is used at a time.
struct ConnectionSettings
{
    enum class Kind
    {
        Serial,
        Tcp,
        Simulated
    };

    Kind kind = Kind::Serial;
    // Serial (libmodbus RTU).
    QString port;      // /dev/ttyUSB0, a pty path, COM3 ...
    int baud = 19200;  // 1200 ... 115200
    char parity = 'N'; // 'N', 'E', 'O'
    int dataBits = 8;
    int stopBits = 1;
    // Modbus TCP gateway.
    QString host = QStringLiteral("127.0.0.1");
    int tcpPort = 502;
    // In-process simulated bus: a device list such as "dbu200@1,dbu400@150,dcpid@7".
    QString simSpec;

    int timeoutMs = 200; // response timeout per attempt
    // Extra attempts after the first (more on a noisy line, see RetryPolicy). 3: with 5 % of
    // the replies lost and a few late, a restore of a whole drive finishes in one run.
    int retries = 3;
    int byteTimeoutMs = 0; // 0: derived from the baud rate

    // Empty when the settings are usable; otherwise what is wrong and what is allowed.
    QString validate() const;
    QString describe() const; // "/dev/ttyUSB0 19200 8N1", "tcp 10.0.0.5:502", "sim dbu200@1"
    // Time one character takes on the wire (start + data + parity + stop bits), in ms.
    double charTimeMs() const;
    int effectiveByteTimeoutMs() const;
};

} // namespace opentop
