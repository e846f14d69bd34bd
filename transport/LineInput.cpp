// What LineInput does the same on every system; the waits and reads are LineInput_posix.cpp
// and LineInput_win.cpp.
#include "transport/LineInput.h"

#include <QElapsedTimer>
#include <algorithm>
#include <modbus.h>

namespace opentop {

namespace {

constexpr int kChunk = MODBUS_TCP_MAX_ADU_LENGTH; // large enough for RTU too

} // namespace

QByteArray LineInput::readWaiting(int limit) const
{
    QByteArray bytes;
    char chunk[kChunk];
    while (bytes.size() < limit && waitReadable(0) == 1) {
        const int n = readSome(chunk, kChunk);
        if (n <= 0)
            break;
        bytes.append(chunk, n);
    }
    return bytes;
}

QByteArray LineInput::readUntilQuiet(double firstWindowMs, int quietMs) const
{
    // A babbling line must not hold the bus for ever.
    const double limitMs = std::max(0.0, firstWindowMs) + 4.0 * quietMs + 100;
    QElapsedTimer timer;
    timer.start();
    QByteArray bytes;
    char chunk[kChunk];
    double window = std::max(0.0, firstWindowMs);
    while (double(timer.elapsed()) < limitMs && waitReadable(window) == 1) {
        const int n = readSome(chunk, kChunk);
        if (n <= 0)
            break;
        bytes.append(chunk, n);
        window = quietMs; // quiet again for a whole frame time after every byte
    }
    return bytes;
}

} // namespace opentop
