#pragma once

#include "sim/SimOptions.h"

#include <QObject>
#include <memory>

namespace opentop {

class ConsoleInput;
class PtySimServer;
class QuitSignals;
class SimBus;
class SimConsole;
class TcpSimServer;

// opentop-sim: options, the bus, its servers, the stdin console and clean shutdown on
// SIGINT/SIGTERM/quit (exit 0, the pty symlink and its lock removed); on Windows on the
// console's Ctrl-C (QuitSignals), serving TCP only (PtySimServer_win.cpp refuses a pty).
class SimApp : public QObject
{
    Q_OBJECT
public:
    explicit SimApp(QObject* parent = nullptr);
    ~SimApp() override;

    // Sets everything up from the command line (with the program name first). Returns an exit
    // code when the program should end at once (--help: 0, bad arguments or a --pty link
    // another simulator serves: 2, failure: 1), or -1 when the event loop should run.
    int start(const QStringList& arguments);
    void shutdown();

private:
    void onStdin(const QByteArray& bytes, bool eof);
    void onSignal();

    SimOptions m_options;
    std::shared_ptr<SimBus> m_bus;
    std::unique_ptr<SimConsole> m_console;
    PtySimServer* m_pty = nullptr;
    TcpSimServer* m_tcp = nullptr;
    ConsoleInput* m_stdin = nullptr;
    QuitSignals* m_signals = nullptr;
    QByteArray m_stdinBuffer;
};

} // namespace opentop
