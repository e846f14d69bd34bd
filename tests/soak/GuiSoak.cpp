#include "tests/soak/GuiSoak.h"

#include <QProcessEnvironment>
#include <QRegularExpression>

namespace opentop::soak {

GuiSoak::GuiSoak(const QString& program, int baud, int pollMs, QObject* parent)
    : SoakPart(parent)
    , m_program(program)
    , m_baud(baud)
    , m_pollMs(pollMs)
{
    connect(&m_process, &QProcess::readyReadStandardOutput, this, &GuiSoak::readLines);
    connect(&m_process, &QProcess::finished, this, [this](int code, QProcess::ExitStatus status) {
        if (!m_stopping)
            emit failed(QStringLiteral("gui: opentop ended (%1 %2); its stderr is in %3")
                            .arg(status == QProcess::NormalExit ? QStringLiteral("exit code")
                                                                : QStringLiteral("crashed, code"))
                            .arg(code)
                            .arg(stderrPath()));
    });
}

GuiSoak::~GuiSoak()
{
    stop();
}

QString GuiSoak::stderrPath() const
{
    return m_home.filePath(QStringLiteral("opentop-stderr.log"));
}

bool GuiSoak::start(const QString& pty, QString* error)
{
    if (!m_home.isValid()) {
        *error = QStringLiteral("no temporary directory: ") + m_home.errorString();
        return false;
    }
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    if (!env.contains(QStringLiteral("QT_QPA_PLATFORM")))
        env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    env.insert(QStringLiteral("XDG_CONFIG_HOME"), m_home.filePath(QStringLiteral("config")));
    m_process.setProcessEnvironment(env);
    m_process.setStandardErrorFile(stderrPath());
    m_process.start(m_program, {QStringLiteral("--port"), pty, QStringLiteral("--baud"),
                                QString::number(m_baud), QStringLiteral("--monitor-all"),
                                QStringLiteral("--poll-ms"), QString::number(m_pollMs),
                                QStringLiteral("--stats-every"), QStringLiteral("1")});
    if (!m_process.waitForStarted(10000)) {
        *error = QStringLiteral("cannot start %1: %2").arg(m_program, m_process.errorString());
        return false;
    }
    return true;
}

void GuiSoak::stop()
{
    if (m_process.state() == QProcess::NotRunning)
        return;
    m_stopping = true;
    m_process.terminate();
    if (!m_process.waitForFinished(10000)) {
        m_process.kill();
        m_process.waitForFinished(2000);
    }
}

bool GuiSoak::parseTotals(const QString& line, Totals* totals)
{
    static const QRegularExpression re(
        QStringLiteral("^monitor: (\\d+) drives, (\\d+) samples, (\\d+) errors, (\\d+) stale, "
                       "(\\d+) trend points, (\\d+) of (\\d+) traffic frames$"));
    const QRegularExpressionMatch m = re.match(line.trimmed());
    if (!m.hasMatch())
        return false;
    totals->drives = m.captured(1).toInt();
    totals->samples = m.captured(2).toLongLong();
    totals->errors = m.captured(3).toLongLong();
    totals->stale = m.captured(4).toInt();
    totals->trendPoints = m.captured(5).toLongLong();
    totals->trafficFrames = m.captured(6).toInt();
    totals->trafficCapacity = m.captured(7).toInt();
    return true;
}

void GuiSoak::readLines()
{
    while (m_process.canReadLine()) {
        const QString line = QString::fromLocal8Bit(m_process.readLine());
        Totals t;
        if (parseTotals(line, &t)) {
            t.atMs = nowMs();
            m_totals = t;
        }
    }
}

} // namespace opentop::soak
