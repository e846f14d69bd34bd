#include "bench/SimulatorProcess.h"

#include <QCoreApplication>

namespace opentop {

SimulatorProcess::~SimulatorProcess()
{
    stop();
}

ConnectionSettings SimulatorProcess::lineSettings(int baud) const
{
    ConnectionSettings s;
    s.kind = ConnectionSettings::Kind::Serial;
    s.port = m_pty;
    s.baud = baud;
    s.parity = 'N';
    return s;
}

void SimulatorProcess::stop()
{
    if (m_process.state() == QProcess::NotRunning)
        return;
    m_process.terminate();
    if (!m_process.waitForFinished(5000))
        m_process.kill();
    m_process.waitForFinished(1000);
}

void SimulatorProcess::command(const QString& line)
{
    m_process.write((line + QLatin1Char('\n')).toLocal8Bit());
    m_process.waitForBytesWritten(1000);
}

bool SimulatorProcess::start(const QStringList& arguments, QString* error)
{
    m_process.setProgram(QCoreApplication::applicationDirPath() + QStringLiteral("/opentop-sim"));
    m_process.setArguments(arguments + QStringList{QStringLiteral("--quiet")});
    m_process.start();
    if (!m_process.waitForStarted(5000)) {
        *error =
            QStringLiteral("cannot start %1: %2").arg(m_process.program(), m_process.errorString());
        return false;
    }
    for (;;) {
        while (!m_process.canReadLine()) {
            if (!m_process.waitForReadyRead(10000)) {
                *error = QStringLiteral("opentop-sim did not get ready: %1")
                             .arg(QString::fromLocal8Bit(m_process.readAllStandardError()));
                return false;
            }
        }
        const QString line = QString::fromLocal8Bit(m_process.readLine()).trimmed();
        if (line.startsWith(QLatin1String("pty: ")))
            m_pty = line.mid(5);
        else if (line.startsWith(QLatin1String("tcp: ")))
            m_tcp = line.mid(5);
        else if (line == QLatin1String("ready"))
            return !m_pty.isEmpty() || !m_tcp.isEmpty();
    }
}

} // namespace opentop
