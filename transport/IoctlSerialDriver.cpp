#include "IoctlSerialDriver.h"

#include <cerrno>
#include <linux/serial.h>
#include <modbus.h>
#include <sys/ioctl.h>

namespace opentop {

IoctlSerialDriver::IoctlSerialDriver(int fd, _modbus* ctx)
    : m_fd(fd)
    , m_ctx(ctx)
{
}

int IoctlSerialDriver::getRs485(Rs485* state)
{
    serial_rs485 rs485{};
    if (::ioctl(m_fd, TIOCGRS485, &rs485) < 0)
        return errno;
    state->flags = rs485.flags;
    state->delayBeforeMs = rs485.delay_rts_before_send;
    state->delayAfterMs = rs485.delay_rts_after_send;
    return 0;
}

int IoctlSerialDriver::setRs485(Rs485* state)
{
    // Fields this struct does not carry (padding, addresses) go in as the driver has them.
    serial_rs485 rs485{};
    ::ioctl(m_fd, TIOCGRS485, &rs485);
    rs485.flags = state->flags;
    rs485.delay_rts_before_send = state->delayBeforeMs;
    rs485.delay_rts_after_send = state->delayAfterMs;
    if (::ioctl(m_fd, TIOCSRS485, &rs485) < 0)
        return errno;
    state->flags = rs485.flags;
    state->delayBeforeMs = rs485.delay_rts_before_send;
    state->delayAfterMs = rs485.delay_rts_after_send;
    return 0;
}

int IoctlSerialDriver::useRts(bool highWhileSending, int delayUs, Rts* readBack)
{
    // libmodbus 3.1.6 ignores a failing TIOCMGET/TIOCMSET (modbus_rtu_set_rts returns 0 on a
    // pty): ask the line itself, before and after.
    int lines = 0;
    if (::ioctl(m_fd, TIOCMGET, &lines) < 0)
        return errno;
    if (modbus_rtu_set_rts(m_ctx, highWhileSending ? MODBUS_RTU_RTS_UP : MODBUS_RTU_RTS_DOWN) < 0)
        return errno;
    int err = 0;
    if (delayUs > 0 && modbus_rtu_set_rts_delay(m_ctx, delayUs) < 0)
        err = errno;
    else if (::ioctl(m_fd, TIOCMGET, &lines) < 0)
        err = errno;
    else if (bool(lines & TIOCM_RTS) == highWhileSending)
        err = ENOTSUP; // RTS did not go to its idle level: the driver ignores it
    if (err != 0) {
        modbus_rtu_set_rts(m_ctx, MODBUS_RTU_RTS_NONE);
        return err;
    }
    readBack->highWhileSending = modbus_rtu_get_rts(m_ctx) == MODBUS_RTU_RTS_UP;
    readBack->delayUs = modbus_rtu_get_rts_delay(m_ctx);
    return 0;
}

int IoctlSerialDriver::getLowLatency(bool* on)
{
    serial_struct serial{};
    if (::ioctl(m_fd, TIOCGSERIAL, &serial) < 0)
        return errno;
    *on = (serial.flags & ASYNC_LOW_LATENCY) != 0;
    return 0;
}

int IoctlSerialDriver::setLowLatency(bool on)
{
    serial_struct serial{};
    if (::ioctl(m_fd, TIOCGSERIAL, &serial) < 0)
        return errno;
    if (on)
        serial.flags |= ASYNC_LOW_LATENCY;
    else
        serial.flags &= ~ASYNC_LOW_LATENCY;
    if (::ioctl(m_fd, TIOCSSERIAL, &serial) < 0)
        return errno;
    return 0;
}

} // namespace opentop
