// LineInput on POSIX: the descriptor (a serial device, a pty or a socket) through ppoll and read.
#include "transport/LineInput.h"

#include "transport/LibmodbusContext.h"
#include "transport/ModbusBackend.h"

#include <QElapsedTimer>
#include <algorithm>
#include <cerrno>
#include <poll.h>
#include <unistd.h>

namespace opentop {

namespace {

constexpr double kSliceMs = 20; // waits are sliced so that an interrupt is seen quickly

} // namespace

LineInput::LineInput(const LibmodbusContext& context, const ModbusBackend& backend)
    : m_fd(context.socket())
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

} // namespace opentop
