#include "transport/IoctlSerialDriver.h"

#include <cerrno>
#include <linux/serial.h>
#include <modbus.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <unistd.h>

namespace opentop {

namespace {

struct Rate
{
    int baud;
    speed_t speed;
};
// The rates both families offer that termios names (14400 and 28800 have no constant; libmodbus
// cannot open them either).
constexpr Rate kRates[] = {{1200, B1200},   {2400, B2400},   {4800, B4800},   {9600, B9600},
                           {19200, B19200}, {38400, B38400}, {57600, B57600}, {115200, B115200}};

} // namespace

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

namespace opentop {

int IoctlSerialDriver::drainOutput()
{
    return ::tcdrain(m_fd) < 0 ? errno : 0;
}

int IoctlSerialDriver::setFormat(const LineFormat& format, LineFormat* readBack)
{
    speed_t speed = 0;
    for (const Rate& r : kRates)
        if (r.baud == format.baud)
            speed = r.speed;
    if (speed == 0)
        return EINVAL;
    termios tio{};
    if (::tcgetattr(m_fd, &tio) < 0)
        return errno;
    ::cfsetispeed(&tio, speed);
    ::cfsetospeed(&tio, speed);
    tio.c_cflag &= ~(CSIZE | PARENB | PARODD | CSTOPB);
    tio.c_cflag |= format.dataBits == 7 ? CS7 : CS8;
    if (format.parity != 'N')
        tio.c_cflag |= PARENB | (format.parity == 'O' ? PARODD : 0);
    if (format.stopBits == 2)
        tio.c_cflag |= CSTOPB;
    // As libmodbus sets it when it opens a port: parity checked on input only with parity.
    if (format.parity != 'N')
        tio.c_iflag |= INPCK;
    else
        tio.c_iflag &= ~INPCK;
    if (::tcsetattr(m_fd, TCSADRAIN, &tio) < 0)
        return errno;
    if (readBack)
        *readBack = formatOf(m_fd);
    return 0;
}

LineFormat IoctlSerialDriver::formatOf(int fd)
{
    termios tio{};
    LineFormat f;
    if (::tcgetattr(fd, &tio) < 0) // TCGETS; on a pty master: its slave's settings
        return f;
    const speed_t speed = ::cfgetospeed(&tio);
    for (const Rate& r : kRates)
        if (r.speed == speed)
            f.baud = r.baud;
    f.dataBits = (tio.c_cflag & CSIZE) == CS7 ? 7 : 8;
    const bool parity = (tio.c_cflag & PARENB) || (tio.c_iflag & INPCK);
    f.parity = !parity ? 'N' : (tio.c_cflag & PARODD) ? 'O' : 'E';
    f.stopBits = (tio.c_cflag & CSTOPB) ? 2 : 1;
    return f;
}

} // namespace opentop
