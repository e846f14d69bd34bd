#pragma once

#include "transport/ConnectionSettings.h"

#include <QProcess>
#include <QString>
#include <QStringList>

namespace opentop {

// opentop-sim (next to this executable) on a pty, and as a Modbus TCP gateway when asked
// (--tcp), stopped when this goes. Its console stays open on stdin for commands.
class SimulatorProcess
{
public:
    ~SimulatorProcess();

    // Starts it with `arguments` (plus --quiet); false with *error when it does not get ready.
    bool start(const QStringList& arguments, QString* error);
    QString pty() const { return m_pty; }
    // "HOST:PORT" when started with --tcp, else empty.
    QString tcp() const { return m_tcp; }
    // Sends one console command ("input 3 1").
    void command(const QString& line);
    // Its pty as a serial line at `baud`, 8N1 (ptys refuse even and odd parity).
    ConnectionSettings lineSettings(int baud) const;
    void stop();

private:
    QProcess m_process;
    QString m_pty;
    QString m_tcp;
};

} // namespace opentop
