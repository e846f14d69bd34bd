#pragma once

#include <QByteArray>
#include <QObject>
#include <memory>

class QSocketNotifier;

namespace opentop {

// The simulator's console: what is typed on, or piped into, standard input, delivered on the
// event loop as it arrives, and its end once. POSIX (ConsoleInput_posix.cpp): a notifier on the
// descriptor, which stays blocking (it may be the user's terminal, shared with the shell).
// Windows (ConsoleInput_win.cpp), where a console or a pipe cannot be waited for on the event
// loop: a thread that reads lines and posts them.
class ConsoleInput : public QObject
{
    Q_OBJECT
public:
    explicit ConsoleInput(QObject* parent = nullptr);
    ~ConsoleInput() override;

    // Nothing more is delivered.
    void stop();

signals:
    // `bytes` may be empty when `atEnd`.
    void received(const QByteArray& bytes, bool atEnd);

private:
#ifdef Q_OS_WIN
    struct Reader;
    std::shared_ptr<Reader> m_reader; // shared with its thread, which may outlive this
#else
    void onReadable();
    QSocketNotifier* m_notifier = nullptr;
#endif
};

} // namespace opentop
