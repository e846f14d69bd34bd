#include "transport/ComPortDriver_win.h"

#include "transport/WinError_win.h"

#include <windows.h>

namespace opentop {

ComPortDriver::ComPortDriver(void* handle)
    : m_handle(handle)
{
}

int ComPortDriver::getRs485(Rs485* state)
{
    Q_UNUSED(state);
    return m_handle ? ENOTSUP : EBADF;
}

int ComPortDriver::setRs485(Rs485* state)
{
    Q_UNUSED(state);
    return m_handle ? ENOTSUP : EBADF;
}

int ComPortDriver::useRts(bool highWhileSending, int delayUs, Rts* readBack)
{
    // libmodbus switches RTS through ioctls, which its Windows build does not have.
    Q_UNUSED(highWhileSending);
    Q_UNUSED(delayUs);
    Q_UNUSED(readBack);
    return m_handle ? ENOTSUP : EBADF;
}

int ComPortDriver::getLowLatency(bool* on)
{
    Q_UNUSED(on);
    return m_handle ? ENOTSUP : EBADF;
}

int ComPortDriver::setLowLatency(bool on)
{
    Q_UNUSED(on);
    return m_handle ? ENOTSUP : EBADF;
}

int ComPortDriver::drainOutput()
{
    if (!m_handle)
        return EBADF;
    // Returns once the driver has sent everything written (libmodbus writes synchronously).
    return FlushFileBuffers(m_handle) ? 0 : WinError::toErrno(GetLastError());
}

int ComPortDriver::setFormat(const LineFormat& format, LineFormat* readBack)
{
    if (!m_handle)
        return EBADF;
    DCB dcb{};
    dcb.DCBlength = sizeof dcb;
    if (!GetCommState(m_handle, &dcb))
        return WinError::toErrno(GetLastError());
    dcb.BaudRate = DWORD(format.baud);
    dcb.ByteSize = BYTE(format.dataBits == 7 ? 7 : 8);
    dcb.Parity = format.parity == 'E' ? EVENPARITY : format.parity == 'O' ? ODDPARITY : NOPARITY;
    dcb.fParity = format.parity != 'N';
    dcb.StopBits = format.stopBits == 2 ? TWOSTOPBITS : ONESTOPBIT;
    if (!SetCommState(m_handle, &dcb))
        return WinError::toErrno(GetLastError());
    if (readBack) {
        DCB back{};
        back.DCBlength = sizeof back;
        if (!GetCommState(m_handle, &back))
            return WinError::toErrno(GetLastError());
        readBack->baud = int(back.BaudRate);
        readBack->dataBits = back.ByteSize;
        readBack->parity = back.Parity == EVENPARITY ? 'E' : back.Parity == ODDPARITY ? 'O' : 'N';
        readBack->stopBits = back.StopBits == TWOSTOPBITS ? 2 : 1;
    }
    return 0;
}

} // namespace opentop
