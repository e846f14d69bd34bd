// LineInput on Windows: a Modbus TCP connection is a Winsock socket (select and recv); a COM
// port is the HANDLE libmodbus opened (LibmodbusContext::commHandle). A COM port has no
// readiness wait with a timeout on a handle opened without overlapped I/O, as libmodbus opens
// it, so waits ask the driver how many bytes it holds (ClearCommError's cbInQue) every
// millisecond, and reads take what is there (ReadFile with timeouts that return at once).
// libmodbus reads with ReadFile too, into a buffer it always empties before it returns, so
// nothing it has read is missed here.
#include "transport/LineInput.h"

#include "transport/LibmodbusContext.h"
#include "transport/ModbusBackend.h"
#include "transport/WinError_win.h"

#include <QElapsedTimer>
#include <algorithm>
#include <cerrno>
#include <windows.h>
#include <winsock2.h>

namespace opentop {

namespace {

constexpr double kSliceMs = 20; // waits are sliced so that an interrupt is seen quickly
// A read after a wait that saw bytes returns at once; this bounds one that finds none.
constexpr DWORD kReadBoundMs = 20;

// Bytes the COM port's driver holds; -1 when it cannot say (the read that follows tells why).
long comBytesWaiting(HANDLE port)
{
    DWORD errors = 0;
    COMSTAT status{};
    if (!ClearCommError(port, &errors, &status))
        return -1;
    return long(status.cbInQue);
}

// 1 readable, 0 timed out, -1 error: select() on the socket for at most `ms`.
int socketReadable(SOCKET s, double ms)
{
    fd_set read;
    FD_ZERO(&read);
    FD_SET(s, &read);
    const auto us = static_cast<long>(std::max(0.0, ms) * 1000);
    timeval tv{us / 1000000, us % 1000000};
    return select(0, &read, nullptr, nullptr, &tv);
}

} // namespace

LineInput::LineInput(const LibmodbusContext& context, const ModbusBackend& backend)
    : m_fd(context.socket())
    , m_comm(context.commHandle())
    , m_backend(backend)
{
}

int LineInput::waitReadable(double timeoutMs) const
{
    if (m_fd < 0 && !m_comm)
        return 0;
    QElapsedTimer timer;
    timer.start();
    for (;;) {
        if (m_backend.interrupted())
            return -1;
        const double left = timeoutMs - double(timer.nsecsElapsed()) / 1e6;
        if (m_comm) {
            if (comBytesWaiting(m_comm) != 0)
                return 1; // bytes, or an error the read that follows reports
            if (left <= 0)
                return 0;
            // A millisecond (the worker thread asks for a 1 ms timer resolution, ModbusClient-
            // Worker); shorter waits yield the core and look again.
            Sleep(left >= 1 ? 1 : 0);
            continue;
        }
        const int rc = socketReadable(SOCKET(m_fd), std::clamp(left, 0.0, kSliceMs));
        if (rc != 0)
            return 1; // data, hangup or error: the read that follows tells which
        if (left <= kSliceMs)
            return 0;
    }
}

int LineInput::readSome(char* buffer, int maximum) const
{
    if (m_comm) {
        // Whatever has arrived, at once; when nothing has, the first byte within kReadBoundMs.
        COMMTIMEOUTS timeouts{};
        GetCommTimeouts(m_comm, &timeouts); // the write timeouts stay libmodbus'
        timeouts.ReadIntervalTimeout = MAXDWORD;
        timeouts.ReadTotalTimeoutMultiplier = MAXDWORD;
        timeouts.ReadTotalTimeoutConstant = kReadBoundMs;
        DWORD got = 0;
        if (!SetCommTimeouts(m_comm, &timeouts) ||
            !ReadFile(m_comm, buffer, DWORD(maximum), &got, nullptr)) {
            errno = WinError::toErrno(GetLastError());
            return -1;
        }
        if (got == 0) {
            errno = EAGAIN; // a serial line has no end of stream: nothing came after all
            return -1;
        }
        return int(got);
    }
    if (m_fd < 0) {
        errno = EBADF;
        return -1;
    }
    const int n = recv(SOCKET(m_fd), buffer, maximum, 0);
    if (n == SOCKET_ERROR) {
        errno = WinError::toErrno(unsigned(WSAGetLastError()));
        return -1;
    }
    return n;
}

} // namespace opentop
