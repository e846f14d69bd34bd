#include "tests/soak/SoakSim.h"

#include <QElapsedTimer>

namespace opentop::soak {

SoakSim::SoakSim(QObject* parent)
    : QObject(parent)
{
    connect(&m_process, &QProcess::finished, this, [this](int code, QProcess::ExitStatus status) {
        if (!m_stopping)
            emit died(QStringLiteral("opentop-sim ended (%1 %2): %3")
                          .arg(status == QProcess::NormalExit ? QStringLiteral("exit code")
                                                              : QStringLiteral("crashed, code"))
                          .arg(code)
                          .arg(QString::fromLocal8Bit(m_process.readAllStandardError()).trimmed()));
    });
}

SoakSim::~SoakSim()
{
    stop();
}

bool SoakSim::start(const QString& program, const QString& devices, int baud, QString* error)
{
    // --quiet: no frame trace (an hour of 247 drives would be gigabytes).
    m_process.start(program, {QStringLiteral("--devices"), devices, QStringLiteral("--pty"),
                              QStringLiteral("--baud"), QString::number(baud),
                              QStringLiteral("--wire-timing"), QStringLiteral("--quiet")});
    if (!m_process.waitForStarted(10000)) {
        *error = QStringLiteral("cannot start %1: %2").arg(program, m_process.errorString());
        return false;
    }
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < 20000) {
        if (!m_process.canReadLine() && !m_process.waitForReadyRead(1000)) {
            if (m_process.state() != QProcess::Running)
                break;
            continue;
        }
        while (m_process.canReadLine()) {
            const QString line = QString::fromLocal8Bit(m_process.readLine()).trimmed();
            if (line.startsWith(QLatin1String("pty: ")))
                m_pty = line.mid(5);
            else if (line == QLatin1String("ready") && !m_pty.isEmpty())
                return true;
        }
    }
    *error = QStringLiteral("opentop-sim did not say ready: %1")
                 .arg(QString::fromLocal8Bit(m_process.readAllStandardError()).trimmed());
    return false;
}

void SoakSim::stop()
{
    if (m_process.state() == QProcess::NotRunning)
        return;
    m_stopping = true;
    m_process.terminate();
    if (!m_process.waitForFinished(5000)) {
        m_process.kill();
        m_process.waitForFinished(2000);
    }
}

} // namespace opentop::soak
