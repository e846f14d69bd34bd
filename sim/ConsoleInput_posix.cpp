#include "sim/ConsoleInput.h"

#include <QSocketNotifier>
#include <cerrno>
#include <unistd.h>

namespace opentop {

ConsoleInput::ConsoleInput(QObject* parent)
    : QObject(parent)
    , m_notifier(new QSocketNotifier(STDIN_FILENO, QSocketNotifier::Read, this))
{
    connect(m_notifier, &QSocketNotifier::activated, this, &ConsoleInput::onReadable);
}

ConsoleInput::~ConsoleInput() = default;

void ConsoleInput::stop()
{
    m_notifier->setEnabled(false);
}

void ConsoleInput::onReadable()
{
    // One read per notification: the notifier says a read will not block.
    char chunk[1024];
    const ssize_t n = ::read(STDIN_FILENO, chunk, sizeof chunk);
    const bool eof = n == 0 || (n < 0 && errno != EAGAIN && errno != EINTR);
    if (eof) // no console (stdin at its end, e.g. /dev/null)
        m_notifier->setEnabled(false);
    emit received(n > 0 ? QByteArray(chunk, int(n)) : QByteArray(), eof);
}

} // namespace opentop
