#pragma once

#include <QString>

struct _modbus; // libmodbus' modbus_t, kept out of this header

namespace opentop {

// A COM port as libmodbus holds it on Windows. libmodbus 3.1 opens the port itself
// (CreateFileA, exclusive) and keeps the HANDLE private: modbus_get_socket() is -1 there, yet
// the transport must wait for and read bytes beside it (LineInput) and switch the line's format
// (ComPortDriver). handleOf() reads the HANDLE out of the context, whose layout (libmodbus
// 3.1.5-3.1.7: modbus-private.h, modbus-rtu-private.h) is mirrored, and trusts it only when
// every field it can check against the public API agrees and the handle is a serial port at
// the context's rate. Windows only.
class ComPort
{
public:
    // The name CreateFile takes: "COM12" as \\.\COM12 (COM1-COM9 work either way, COM10 and up
    // only so); anything else as given.
    static QString devicePath(const QString& port);
    // The connected RTU context's HANDLE; null (logged) when it cannot be found safely.
    static void* handleOf(_modbus* ctx);
};

} // namespace opentop
