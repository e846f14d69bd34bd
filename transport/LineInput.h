#pragma once

#include <QByteArray>

namespace opentop {

class LibmodbusContext;
class ModbusBackend;

// The connection's descriptor read directly, beside libmodbus: waits in short slices so that the
// backend's interrupt flag ends them quickly, reads that survive a signal, and the two ways a
// master throws bytes away (what is already waiting, and all that comes until the line falls
// quiet). A value made for one use; it does not own the descriptor. On Windows
// (LineInput_win.cpp) the descriptor is a Winsock socket, and a COM port is read through the
// HANDLE libmodbus keeps (LibmodbusContext::commHandle).
class LineInput
{
public:
    LineInput(const LibmodbusContext& context, const ModbusBackend& backend);

    // 1 readable, 0 timed out, -1 interrupted; waits in short slices.
    int waitReadable(double timeoutMs) const;
    // read() on the descriptor: bytes read, 0 at end of stream, -1 (errno) on error.
    int readSome(char* buffer, int maximum) const;
    // The bytes already waiting, up to about `limit`; stops at a failed read (the next send
    // reports a failed port).
    QByteArray readWaiting(int limit) const;
    // Reads until nothing has arrived for `firstWindowMs`, then for `quietMs` after every byte;
    // a babbling line gives up after the first window, four quiet times and 100 ms.
    QByteArray readUntilQuiet(double firstWindowMs, int quietMs) const;

private:
    int m_fd;
#ifdef Q_OS_WIN
    void* m_comm; // a COM port's HANDLE, else null
#endif
    const ModbusBackend& m_backend;
};

} // namespace opentop
