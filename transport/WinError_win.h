#pragma once

namespace opentop {

// The system's error codes on Windows as the errno values the transport classifies
// (LibmodbusContext::isFatal, replyFault) and reports. Windows only.
class WinError
{
public:
    // A Win32 or Winsock error code (GetLastError, WSAGetLastError) as an errno.
    static int toErrno(unsigned long code);
    // errno after a failed modbus_connect: 0 when libmodbus' serial open left it alone (then
    // the system's last error says why), a Winsock code from its TCP connect, else itself.
    static int connectErrno(int err);
    // Text for the POSIX codes MinGW adds (ECONNREFUSED, ETIMEDOUT, ...), which the Windows C
    // library's strerror calls "Unknown error"; null for any other.
    static const char* posixText(int err);
};

} // namespace opentop
