#include "transport/WinError_win.h"

#include <cerrno>
#include <windows.h>
#include <winsock2.h>

namespace opentop {

namespace {

constexpr unsigned long kFirstWinsockCode = WSABASEERR; // 10000

} // namespace

int WinError::toErrno(unsigned long code)
{
    switch (code) {
    case ERROR_SUCCESS:
        return 0;
    case ERROR_FILE_NOT_FOUND:
    case ERROR_PATH_NOT_FOUND:
        return ENOENT;
    case ERROR_ACCESS_DENIED:
    case ERROR_SHARING_VIOLATION:
        return EBUSY; // a COM port another program has open (ports open exclusively)
    case ERROR_INVALID_HANDLE:
        return EBADF;
    case ERROR_INVALID_PARAMETER:
        return EINVAL; // e.g. a rate or format the adapter's driver refuses
    case ERROR_DEVICE_NOT_CONNECTED:
    case ERROR_DEV_NOT_EXIST:
    case ERROR_BAD_COMMAND: // an unplugged USB adapter's handle
    case ERROR_GEN_FAILURE:
    case ERROR_OPERATION_ABORTED:
        return EIO;
    case WSAECONNREFUSED:
        return ECONNREFUSED;
    case WSAECONNRESET:
        return ECONNRESET;
    case WSAECONNABORTED:
        return ECONNABORTED;
    case WSAENOTCONN:
    case WSAESHUTDOWN:
        return ENOTCONN;
    case WSAETIMEDOUT:
        return ETIMEDOUT;
    case WSAEHOSTUNREACH:
        return EHOSTUNREACH;
    case WSAENETUNREACH:
        return ENETUNREACH;
    case WSAEWOULDBLOCK:
        return EAGAIN;
    case WSAEINTR:
        return EINTR;
    case WSAENOTSOCK:
        return EBADF;
    default:
        return EIO;
    }
}

int WinError::connectErrno(int err)
{
    if (err == 0)
        return toErrno(GetLastError());
    if (unsigned(err) >= kFirstWinsockCode)
        return toErrno(unsigned(err));
    return err;
}

const char* WinError::posixText(int err)
{
    // The C library's words on Linux, where the same failures are reported.
    switch (err) {
    case ECONNREFUSED:
        return "Connection refused";
    case ECONNRESET:
        return "Connection reset by peer";
    case ECONNABORTED:
        return "Software caused connection abort";
    case ENOTCONN:
        return "Transport endpoint is not connected";
    case ETIMEDOUT:
        return "Connection timed out";
    case EHOSTUNREACH:
        return "No route to host";
    case ENETUNREACH:
        return "Network is unreachable";
    case ENOTSUP:
        return "Operation not supported";
    default:
        return nullptr;
    }
}

} // namespace opentop
