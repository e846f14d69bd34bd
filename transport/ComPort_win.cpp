#include "transport/ComPort_win.h"

#include "transport/TransportLog.h"

#include <algorithm>
#include <cstdint>
#include <modbus.h>
#include <windows.h>

namespace opentop {

namespace {

// libmodbus 3.1.5-3.1.7's private structures on Win64 (3.1.8 added a field to modbus_t: the
// checks below then fail and no handle is used).
struct TimeVal
{
    long sec;
    long usec;
};
struct ModbusMirror
{
    int slave;
    int s;
    int debug;
    int errorRecovery;
    TimeVal responseTimeout;
    TimeVal byteTimeout;
    TimeVal indicationTimeout;
    const void* backend;
    void* backendData;
};
struct RtuMirror
{
    char* device;
    int baud;
    uint8_t dataBit;
    uint8_t stopBit;
    char parity;
    HANDLE fd; // struct win32_ser's first member
};

bool sameTime(const TimeVal& mirrored, uint32_t sec, uint32_t usec)
{
    return uint32_t(mirrored.sec) == sec && uint32_t(mirrored.usec) == usec;
}

// The modbus_t fields the public API also gives: all must agree before backendData is followed.
bool contextMatches(modbus_t* ctx, const ModbusMirror& m)
{
    uint32_t sec = 0, usec = 0;
    if (modbus_get_response_timeout(ctx, &sec, &usec) != 0 ||
        !sameTime(m.responseTimeout, sec, usec))
        return false;
    if (modbus_get_byte_timeout(ctx, &sec, &usec) != 0 || !sameTime(m.byteTimeout, sec, usec))
        return false;
    if (modbus_get_indication_timeout(ctx, &sec, &usec) != 0 ||
        !sameTime(m.indicationTimeout, sec, usec))
        return false;
    return m.slave == modbus_get_slave(ctx) && m.s == modbus_get_socket(ctx) &&
           m.backendData != nullptr;
}

bool rtuMatches(const RtuMirror& rtu)
{
    if (rtu.baud <= 0 || rtu.dataBit < 5 || rtu.dataBit > 8 || rtu.stopBit < 1 || rtu.stopBit > 2 ||
        (rtu.parity != 'N' && rtu.parity != 'E' && rtu.parity != 'O'))
        return false;
    if (rtu.fd == nullptr || rtu.fd == INVALID_HANDLE_VALUE ||
        GetFileType(rtu.fd) != FILE_TYPE_CHAR)
        return false;
    DCB dcb{};
    dcb.DCBlength = sizeof dcb;
    return GetCommState(rtu.fd, &dcb) && dcb.BaudRate == DWORD(rtu.baud) &&
           dcb.ByteSize == rtu.dataBit;
}

} // namespace

QString ComPort::devicePath(const QString& port)
{
    // No QRegularExpression: this runs on the bus thread, and with MinGW a thread's
    // thread_local storage is freed before the destructor of Qt's per-thread regex JIT stack
    // runs, which crashed every program when its bus thread ended.
    const bool com =
        port.size() > 3 && port.startsWith(QLatin1String("COM"), Qt::CaseInsensitive) &&
        std::all_of(port.begin() + 3, port.end(),
                    [](QChar c) { return c >= QLatin1Char('0') && c <= QLatin1Char('9'); });
    return com ? QStringLiteral("\\\\.\\") + port : port;
}

void* ComPort::handleOf(_modbus* ctx)
{
    if (!ctx)
        return nullptr;
    if (libmodbus_version_major != 3 || libmodbus_version_minor != 1 ||
        libmodbus_version_micro < 5 || libmodbus_version_micro > 7) {
        qCWarning(lcTransport) << "libmodbus" << libmodbus_version_major << libmodbus_version_minor
                               << libmodbus_version_micro
                               << "is not one whose COM port handle is known: the line is "
                                  "read through libmodbus only";
        return nullptr;
    }
    const auto* m = reinterpret_cast<const ModbusMirror*>(ctx);
    if (!contextMatches(ctx, *m) || !rtuMatches(*static_cast<const RtuMirror*>(m->backendData))) {
        qCWarning(lcTransport) << "libmodbus' COM port handle not found: the line is read "
                                  "through libmodbus only";
        return nullptr;
    }
    return static_cast<const RtuMirror*>(m->backendData)->fd;
}

} // namespace opentop
