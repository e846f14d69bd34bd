#include "sim/ReplyScheduler.h"

#include "sim/SimLog.h"

#include <QSocketNotifier>
#include <algorithm>
#include <cerrno>
#include <cstring>
#include <ctime>
#include <sys/prctl.h>
#include <sys/timerfd.h>
#include <unistd.h>

namespace opentop {

ReplyScheduler::ReplyScheduler(Send send, QObject* parent)
    : QObject(parent)
    , m_send(std::move(send))
{
    // The serving thread's waits may otherwise end 50 µs late (Linux's default timer slack).
    ::prctl(PR_SET_TIMERSLACK, 1000UL, 0UL, 0UL, 0UL);
    m_fd = ::timerfd_create(CLOCK_MONOTONIC, TFD_NONBLOCK | TFD_CLOEXEC);
    if (m_fd < 0) {
        qCWarning(lcSim) << "timerfd_create failed:" << strerror(errno);
        return;
    }
    m_notifier = new QSocketNotifier(m_fd, QSocketNotifier::Read, this);
    connect(m_notifier, &QSocketNotifier::activated, this, &ReplyScheduler::onTimer);
}

ReplyScheduler::~ReplyScheduler()
{
    delete m_notifier;
    if (m_fd >= 0)
        ::close(m_fd);
}

qint64 ReplyScheduler::nowNs()
{
    timespec ts{};
    ::clock_gettime(CLOCK_MONOTONIC, &ts);
    return qint64(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

void ReplyScheduler::schedule(const Reply& reply)
{
    const auto at = std::upper_bound(m_pending.begin(), m_pending.end(), reply.dueNs,
                                     [](qint64 due, const Reply& r) { return due < r.dueNs; });
    m_pending.insert(at, reply);
    arm();
}

void ReplyScheduler::clear()
{
    m_pending.clear();
    arm();
}

void ReplyScheduler::arm()
{
    if (m_fd < 0)
        return;
    itimerspec spec{};
    if (!m_pending.isEmpty()) {
        // 0 disarms a timerfd: a due time already past is armed 1 ns ahead instead.
        const qint64 due = std::max<qint64>(m_pending.first().dueNs, 1);
        spec.it_value.tv_sec = time_t(due / 1000000000);
        spec.it_value.tv_nsec = long(due % 1000000000);
    }
    ::timerfd_settime(m_fd, TFD_TIMER_ABSTIME, &spec, nullptr);
}

void ReplyScheduler::onTimer()
{
    quint64 expirations = 0;
    while (::read(m_fd, &expirations, sizeof expirations) > 0) {
    }
    const qint64 now = nowNs();
    while (!m_pending.isEmpty() && m_pending.first().dueNs <= now) {
        const QByteArray bytes = m_pending.takeFirst().bytes;
        m_send(bytes);
    }
    arm();
}

} // namespace opentop
