#include "sim/QuitSignals.h"

#include <QSocketNotifier>
#include <csignal>
#include <fcntl.h>
#include <sys/socket.h>
#include <unistd.h>

namespace opentop {

namespace {

int g_signalWriteFd = -1;

void onPosixSignal(int)
{
    const char byte = 1;
    if (g_signalWriteFd >= 0) {
        // A full pipe already holds a wake-up: nothing to do when the write fails.
        const ssize_t written = ::write(g_signalWriteFd, &byte, 1);
        static_cast<void>(written);
    }
}

} // namespace

QuitSignals::QuitSignals(QObject* parent)
    : QObject(parent)
{
    if (::socketpair(AF_UNIX, SOCK_STREAM, 0, m_fds) != 0)
        return;
    for (int fd : m_fds)
        ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
    g_signalWriteFd = m_fds[0];
    struct sigaction action = {};
    action.sa_handler = onPosixSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    ::sigaction(SIGINT, &action, nullptr);
    ::sigaction(SIGTERM, &action, nullptr);
    ::signal(SIGPIPE, SIG_IGN);
    m_notifier = new QSocketNotifier(m_fds[1], QSocketNotifier::Read, this);
    connect(m_notifier, &QSocketNotifier::activated, this, &QuitSignals::onPipe);
}

QuitSignals::~QuitSignals()
{
    if (g_signalWriteFd == m_fds[0])
        g_signalWriteFd = -1;
    for (int fd : m_fds) {
        if (fd >= 0)
            ::close(fd);
    }
}

void QuitSignals::onPipe()
{
    char byte;
    while (::read(m_fds[1], &byte, 1) > 0) {
    }
    emit received();
}

} // namespace opentop
