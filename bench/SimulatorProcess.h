#pragma once

#include "ConnectionSettings.h"

#include <QProcess>
#include <QString>
#include <QStringList>

namespace opentop {

// opentop-sim (next to this executable) on a pty, stopped when this goes. Its console stays
// open on stdin for commands.
class SimulatorProcess
{
public:
    ~SimulatorProcess();

    // Starts it with `arguments` (plus --quiet); false with *error when it does not get ready.
    bool start(const QStringList& arguments, QString* error);
    QString pty() const { return m_pty; }
    // Its pty as a serial line at `baud`, 8N1 (ptys refuse even and odd parity).
    ConnectionSettings lineSettings(int baud) const;
    void stop();

private:
    QProcess m_process;
    QString m_pty;
};

} // namespace opentop
