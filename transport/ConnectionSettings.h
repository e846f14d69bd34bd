#pragma once

#include "transport/LineFormat.h"

#include <QMap>
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

    // Who switches an RS-485 transceiver between sending and receiving.
    enum class Rs485
    {
        Off,    // the adapter itself (USB–RS-485 adapters do): the driver's state is left alone
        Auto,   // the kernel's RS-485 mode if the driver has it, else RTS from the program
        Kernel, // the kernel's RS-485 mode (TIOCSRS485), for on-board RS-485 UARTs
        Rts     // RTS toggled by libmodbus around each request
    };

    Kind kind = Kind::Serial;
    // Serial (libmodbus RTU).
    QString port;      // /dev/ttyUSB0, a pty path, COM3 ...
    int baud = 19200;  // 1200 ... 115200
    char parity = 'N'; // 'N', 'E', 'O'
    int dataBits = 8;
    int stopBits = 1;
    Rs485 rs485 = Rs485::Off;
    bool rtsHighWhileSending = true; // RTS level while sending (Kernel, Rts, Auto)
    int rtsDelayUs = 0;              // before and after sending; 0: libmodbus' or the driver's own
    bool lowLatency = true;          // ask the driver to pass received bytes on at once
    // Drives that talk another format than the port's (machine number → format): requests to
    // them carry it, and the port is switched between transactions (LineFormat).
    QMap<int, LineFormat> driveLines;
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
    // "/dev/ttyUSB0 19200 8N1", "tcp 10.0.0.5:502", "sim dbu200@1"; the serial line's RS-485
    // and low-latency settings only where they differ from the defaults
    // ("/dev/ttyS1 19200 8N1 rs485=kernel rts=low rts-delay=500us low-latency=off").
    QString describe() const;
    // The command line's names: "off", "auto", "kernel", "rts"; fromName() is false when
    // `name` is none of them.
    static QString rs485Name(Rs485 mode);
    static bool rs485FromName(const QString& name, Rs485* mode);
    static constexpr int kMaxRtsDelayUs = 100000; // the kernel's limit too (100 ms)
    // The port's own format, and setting it (the rest kept).
    LineFormat line() const;
    void setLine(const LineFormat& format);
    // Time one character takes on the wire (start + data + parity + stop bits), in ms.
    double charTimeMs() const;
    int effectiveByteTimeoutMs() const;
};

} // namespace opentop
