#pragma once

#include <QObject>

class QSocketNotifier;

namespace opentop {

// Tells the event loop that the simulator was asked to stop: SIGINT or SIGTERM on POSIX (a
// self-pipe written by the handler, QuitSignals_posix.cpp, which also ignores SIGPIPE), the
// console's Ctrl-C, Ctrl-Break or close on Windows (the console control handler,
// QuitSignals_win.cpp). One at a time per process.
class QuitSignals : public QObject
{
    Q_OBJECT
public:
    explicit QuitSignals(QObject* parent = nullptr);
    ~QuitSignals() override;

signals:
    void received();

private:
#ifndef Q_OS_WIN
    void onPipe();
    QSocketNotifier* m_notifier = nullptr;
    int m_fds[2] = {-1, -1};
#endif
};

} // namespace opentop
