#include "transport/LineInput.h"

#include "transport/ModbusBackend.h"

#include <QElapsedTimer>
#include <algorithm>
#include <cerrno>
#include <modbus.h>
#include <poll.h>
#include <unistd.h>

namespace opentop {

namespace {

constexpr int kChunk = MODBUS_TCP_MAX_ADU_LENGTH; // large enough for RTU too
constexpr double kSliceMs = 20; // waits are sliced so that an interrupt is seen quickly

} // namespace

LineInput::LineInput(int descriptor, const ModbusBackend& backend)
    : m_fd(descriptor)
    , m_backend(backend)
{
}

int LineInput::waitReadable(double timeoutMs) const
{
    if (m_fd < 0)
        return 0;
    QElapsedTimer timer;
    timer.start();
    for (;;) {
        if (m_backend.interrupted())
            return -1;
        const double left = timeoutMs - double(timer.nsecsElapsed()) / 1e6;
        // ppoll: a wait of 1.2 ms must not become 2 ms (a whole millisecond per transaction is
        // 10 % of a fast line's time).
        const double slice = std::clamp(left, 0.0, kSliceMs);
        const auto ns = static_cast<long long>(slice * 1e6);
        const timespec ts{time_t(ns / 1000000000), long(ns % 1000000000)};
        pollfd pfd{m_fd, POLLIN, 0};
        const int rc = ::ppoll(&pfd, 1, &ts, nullptr);
        if (rc > 0)
            return 1; // data, hangup or error: the read that follows tells which
        if (rc < 0 && errno != EINTR)
            return 1;
        if (left <= kSliceMs)
            return 0;
    }
}

int LineInput::readSome(char* buffer, int maximum) const
{
    if (m_fd < 0) {
        errno = EBADF;
        return -1;
    }
    for (;;) {
        const ssize_t n = ::read(m_fd, buffer, size_t(maximum));
        if (n < 0 && errno == EINTR)
            continue;
        return int(n);
    }
}

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
