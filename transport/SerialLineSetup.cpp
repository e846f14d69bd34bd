#include "transport/SerialLineSetup.h"

#include "transport/SerialSysfs.h"
#include "transport/TransportLog.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <cerrno>
#ifdef Q_OS_WIN
#include "transport/WinError_win.h"

#include <cstring>
#else
#include <linux/serial.h>
#endif

namespace opentop {

namespace {

#ifdef Q_OS_WIN
// linux/serial.h's flags, which SerialDriver::Rs485 carries; no Windows driver takes them
// (ComPortDriver answers ENOTSUP).
enum : quint32
{
    SER_RS485_ENABLED = 1u << 0,
    SER_RS485_RTS_ON_SEND = 1u << 1,
    SER_RS485_RTS_AFTER_SEND = 1u << 2,
    SER_RS485_RX_DURING_TX = 1u << 4,
};
#endif

using Rs485 = ConnectionSettings::Rs485;
using Direction = SerialLineReport::Direction;
using LowLatency = SerialLineReport::LowLatency;

QString errorText(int err)
{
#ifdef Q_OS_WIN // qt_error_string takes a Windows error code there, not an errno
    if (const char* text = WinError::posixText(err))
        return QString::fromLatin1(text);
    return QString::fromLocal8Bit(std::strerror(err));
#else
    return qt_error_string(err);
#endif
}

bool highWhileSending(const SerialDriver::Rs485& state)
{
    // The kernel keeps exactly one of the two; RTS_ON_SEND is its default.
    return (state.flags & SER_RS485_RTS_ON_SEND) != 0 ||
           (state.flags & SER_RS485_RTS_AFTER_SEND) == 0;
}

} // namespace

SerialLineReport SerialLineSetup::apply(SerialDriver& driver, const ConnectionSettings& settings,
                                        const SerialSysfs& sysfs)
{
    m_savedRs485.reset();
    m_savedLowLatency.reset();
    SerialLineReport report;
    applyDirection(driver, settings, &report);
    applyLowLatency(driver, settings, sysfs, &report);
    qCDebug(lcTransport) << settings.port << report.text();
    return report;
}

void SerialLineSetup::applyDirection(SerialDriver& driver, const ConnectionSettings& settings,
                                     SerialLineReport* report)
{
    switch (settings.rs485) {
    case Rs485::Off: {
        SerialDriver::Rs485 state;
        if (driver.getRs485(&state) == 0 && (state.flags & SER_RS485_ENABLED)) {
            // Switched on by a device tree or an earlier program: both it and the adapter would
            // switch direction. Not ours to undo, but worth saying.
            report->direction = Direction::KernelLeftOn;
            report->rtsHighWhileSending = highWhileSending(state);
            report->rtsDelayBeforeUs = int(state.delayBeforeMs) * 1000;
            report->rtsDelayAfterUs = int(state.delayAfterMs) * 1000;
        } else {
            report->direction = Direction::Adapter;
        }
        return;
    }
    case Rs485::Kernel:
        if (!tryKernel(driver, settings, report))
            report->direction = Direction::Unavailable;
        return;
    case Rs485::Rts:
        if (!tryRts(driver, settings, report))
            report->direction = Direction::Unavailable;
        return;
    case Rs485::Auto:
        if (!tryKernel(driver, settings, report) && !tryRts(driver, settings, report))
            report->direction = Direction::Unavailable;
        return;
    }
}

bool SerialLineSetup::tryKernel(SerialDriver& driver, const ConnectionSettings& settings,
                                SerialLineReport* report)
{
    SerialDriver::Rs485 found;
    const bool known = driver.getRs485(&found) == 0;
    SerialDriver::Rs485 want = known ? found : SerialDriver::Rs485();
    want.flags |= SER_RS485_ENABLED;
    // Half duplex: no echo of our own request.
    want.flags &=
        ~quint32(SER_RS485_RTS_ON_SEND | SER_RS485_RTS_AFTER_SEND | SER_RS485_RX_DURING_TX);
    want.flags |= settings.rtsHighWhileSending ? SER_RS485_RTS_ON_SEND : SER_RS485_RTS_AFTER_SEND;
    if (settings.rtsDelayUs > 0) {
        // The driver counts whole milliseconds: never shorter than asked.
        const quint32 ms = quint32((settings.rtsDelayUs + 999) / 1000);
        want.delayBeforeMs = ms;
        want.delayAfterMs = ms;
    }
    SerialDriver::Rs485 got = want;
    if (const int err = driver.setRs485(&got)) {
        report->kernelRefusal = errorText(err);
        return false;
    }
    if (known)
        m_savedRs485 = found;
    SerialDriver::Rs485 back;
    if (driver.getRs485(&back) == 0)
        got = back;
    if (!(got.flags & SER_RS485_ENABLED)) {
        report->kernelRefusal =
            QCoreApplication::translate("opentop::Transport", "the driver left it off");
        return false;
    }
    report->direction = Direction::Kernel;
    report->rtsHighWhileSending = highWhileSending(got);
    report->rtsDelayBeforeUs = int(got.delayBeforeMs) * 1000;
    report->rtsDelayAfterUs = int(got.delayAfterMs) * 1000;
    return true;
}

bool SerialLineSetup::tryRts(SerialDriver& driver, const ConnectionSettings& settings,
                             SerialLineReport* report)
{
    SerialDriver::Rts rts;
    if (const int err = driver.useRts(settings.rtsHighWhileSending, settings.rtsDelayUs, &rts)) {
        report->rtsRefusal = errorText(err);
        return false;
    }
    report->direction = Direction::Rts;
    report->rtsHighWhileSending = rts.highWhileSending;
    report->rtsDelayBeforeUs = rts.delayUs;
    report->rtsDelayAfterUs = rts.delayUs;
    return true;
}

void SerialLineSetup::applyLowLatency(SerialDriver& driver, const ConnectionSettings& settings,
                                      const SerialSysfs& sysfs, SerialLineReport* report)
{
    report->usbAdapter = sysfs.isUsb();
    bool on = false;
    const int err = driver.getLowLatency(&on);
    if (err != 0 && !report->usbAdapter && (err == ENOTTY || err == EINVAL)) {
        // A pty, a USB CDC modem without UART settings...: nothing holds bytes back.
        report->lowLatency = LowLatency::NotUart;
        return;
    }
    if (err != 0) {
        report->lowLatency = settings.lowLatency ? LowLatency::Unavailable : LowLatency::Off;
        report->lowLatencyRefusal = errorText(err);
    } else if (on) {
        report->lowLatency = LowLatency::On;
    } else if (!settings.lowLatency) {
        report->lowLatency = LowLatency::Off;
    } else if (const int setErr = driver.setLowLatency(true)) {
        report->lowLatency = LowLatency::Unavailable;
        report->lowLatencyRefusal = errorText(setErr);
    } else {
        m_savedLowLatency = false;
        bool back = false;
        const bool took = driver.getLowLatency(&back) == 0 && back;
        report->lowLatency = took ? LowLatency::On : LowLatency::Unavailable;
    }
    // Read after setting: FTDI's driver sets its latency timer to 1 ms with the flag.
    report->latencyTimerPath = sysfs.latencyTimerPath();
    report->latencyTimerMs = sysfs.latencyTimerMs();
}

int SerialLineSetup::switchFormat(SerialDriver& driver, const LineFormat& format, QString* error)
{
    QElapsedTimer timer;
    timer.start();
    int err = driver.drainOutput();
    LineFormat readBack;
    if (err == 0)
        err = driver.setFormat(format, &readBack);
    if (err == 0 && readBack.baud != format.baud)
        err = EINVAL; // the driver took another rate: the drive would not hear us
    m_switchMicros += timer.nsecsElapsed() / 1000;
    if (err != 0) {
        *error = err == EINVAL ? QCoreApplication::translate("opentop::Transport",
                                                             "the port does not take %1")
                                     .arg(format.text())
                               : errorText(err);
        return err;
    }
    ++m_switches;
    qCDebug(lcTransport) << "line switched to" << format.text();
    return 0;
}

void SerialLineSetup::restore(SerialDriver& driver)
{
    // On an unplugged adapter these fail; the port is going anyway.
    if (m_savedRs485) {
        SerialDriver::Rs485 state = *m_savedRs485;
        driver.setRs485(&state);
    }
    if (m_savedLowLatency)
        driver.setLowLatency(*m_savedLowLatency);
    m_savedRs485.reset();
    m_savedLowLatency.reset();
}

} // namespace opentop
