#pragma once

#include <QString>

namespace opentop {

// What a serial port's driver accepted for RS-485 direction control and low latency, read back
// after SerialLineSetup asked, not what the settings asked for. Empty for TCP and simulated buses.
struct SerialLineReport
{
    enum class Direction
    {
        NotApplicable, // no serial line
        Adapter,       // RS-485 off: the adapter switches direction itself
        KernelLeftOn,  // RS-485 off, but the driver's RS-485 mode was on already: left as it was
        Kernel,        // the kernel's RS-485 mode (TIOCSRS485) is on
        Rts,           // libmodbus raises and drops RTS around each request
        Unavailable    // asked for, but the driver took neither way
    };
    enum class LowLatency
    {
        NotApplicable, // no serial line
        NotUart,       // a pty or another tty without UART settings: no adapter latency
        On,
        Unavailable, // asked for, not accepted by the driver
        Off          // not asked for, and off
    };

    Direction direction = Direction::NotApplicable;
    bool rtsHighWhileSending = true; // Kernel, KernelLeftOn, Rts: as read back
    int rtsDelayBeforeUs = 0;        // Kernel: the driver's delays; Rts: libmodbus' (both sides)
    int rtsDelayAfterUs = 0;
    QString kernelRefusal; // why the kernel's RS-485 mode was refused; empty: accepted/not tried
    QString rtsRefusal;    // why RTS cannot be switched; empty: works/not tried

    LowLatency lowLatency = LowLatency::NotApplicable;
    QString lowLatencyRefusal;
    bool usbAdapter = false;  // the port is a USB–serial adapter (sysfs)
    int latencyTimerMs = -1;  // the adapter's latency timer from sysfs (FTDI); -1: unknown
    QString latencyTimerPath; // that sysfs file, for the fix; empty when there is none

    // The common default latency of USB–serial chips (FTDI's latency timer), assumed for a USB
    // adapter that refused low latency and has no readable latency timer.
    static constexpr int kAssumedUsbLatencyMs = 16;

    bool isEmpty() const
    {
        return direction == Direction::NotApplicable && lowLatency == LowLatency::NotApplicable;
    }
    // One line: "RS-485: kernel (RTS high while sending); low latency: on". Empty when empty.
    QString text() const;
    QString directionText() const;
    QString lowLatencyText() const;
    // How long the adapter may hold received bytes before passing them on, in ms: 0 when there
    // is nothing to allow for (no serial line, not a UART, low latency on, or a port that is no
    // USB adapter); the latency timer read from sysfs when it is above 1 ms; otherwise 16 ms
    // for a USB adapter that did not take low latency.
    int adapterLatencyMs() const;
    // Empty unless adapterLatencyMs() > 0: says so, why, and how to fix it.
    QString latencyWarning() const;
};

} // namespace opentop
