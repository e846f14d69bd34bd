#include "tests/faultmatrix/MatrixSim.h"

#include "tests/faultmatrix/BackupValues.h"

#include <QRegularExpression>
#include <csignal>
#include <sys/prctl.h>

namespace opentop::faultmatrix {

MatrixSim::MatrixSim(const QString& binDir)
    : m_binDir(binDir)
{
}

MatrixSim::~MatrixSim()
{
    stop();
}

bool MatrixSim::start(const QString& devices, const QString& faults, int seed, const QString& link,
                      int baud, QString* error)
{
    QStringList arguments{QStringLiteral("--devices"),
                          devices,
                          QStringLiteral("--wire-timing"),
                          QStringLiteral("--baud"),
                          QString::number(baud),
                          QStringLiteral("--seed"),
                          QString::number(seed),
                          QStringLiteral("--pty"),
                          link,
                          QStringLiteral("--quiet")};
    if (!faults.isEmpty())
        arguments << QStringLiteral("--faults") << faults;
    m_process.setProgram(m_binDir + QStringLiteral("/opentop-sim"));
    m_process.setArguments(arguments);
    // The simulator ends with the matrix, even when the matrix is killed.
    m_process.setChildProcessModifier([] { ::prctl(PR_SET_PDEATHSIG, SIGTERM); });
    m_process.start();
    if (!m_process.waitForStarted(5000)) {
        *error = m_process.errorString();
        return false;
    }
    for (;;) {
        const QString line = readLine(10000);
        if (line.isNull()) {
            *error = QStringLiteral("opentop-sim did not print \"ready\": ") +
                     QString::fromLocal8Bit(m_process.readAllStandardError());
            return false;
        }
        if (line == QLatin1String("ready"))
            return true;
    }
}

void MatrixSim::stop()
{
    if (m_process.state() == QProcess::NotRunning)
        return;
    m_process.terminate();
    if (!m_process.waitForFinished(5000)) {
        m_process.kill();
        m_process.waitForFinished(2000);
    }
}

QString MatrixSim::readLine(int timeoutMs)
{
    while (!m_process.canReadLine()) {
        if (!m_process.waitForReadyRead(timeoutMs))
            return QString();
    }
    return QString::fromLocal8Bit(m_process.readLine()).trimmed();
}

QString MatrixSim::command(const QString& line)
{
    return commands({line}).value(0);
}

QStringList MatrixSim::commands(const QStringList& lines)
{
    QByteArray batch;
    for (const QString& line : lines)
        batch += (line + QLatin1Char('\n')).toLocal8Bit();
    m_process.write(batch);
    QStringList answers;
    for (int i = 0; i < lines.size(); ++i) {
        const QString answer = readLine(10000);
        if (answer.isNull())
            break;
        answers << answer;
    }
    return answers;
}

bool MatrixSim::set(int slave, quint16 address, quint16 value)
{
    return command(QStringLiteral("set %1 0x%2 %3")
                       .arg(slave)
                       .arg(address, 4, 16, QLatin1Char('0'))
                       .arg(value))
        .startsWith(QLatin1String("0x"));
}

QString MatrixSim::key(int slave, const QString& name)
{
    return QStringLiteral("%1/%2").arg(slave).arg(name);
}

QHash<QString, QVector<quint16>> MatrixSim::truth(const QVector<Setting>& settings, QString* error)
{
    QStringList lines;
    for (const Setting& s : settings) {
        for (int i = 0; i < s.registers.size(); ++i)
            lines << QStringLiteral("get %1 0x%2")
                         .arg(s.slave)
                         .arg(s.address + i, 4, 16, QLatin1Char('0'));
    }
    const QStringList answers = commands(lines);
    static const QRegularExpression value(QStringLiteral("^0x[0-9a-f]{4} = (\\d+) "));
    QHash<QString, QVector<quint16>> result;
    int n = 0;
    for (const Setting& s : settings) {
        QVector<quint16> registers;
        for (int i = 0; i < s.registers.size(); ++i, ++n) {
            const QRegularExpressionMatch m = value.match(answers.value(n));
            if (!m.hasMatch()) {
                *error = QStringLiteral("the simulator answered '%1' to '%2'")
                             .arg(answers.value(n), lines.value(n));
                return {};
            }
            registers << quint16(m.captured(1).toUInt());
        }
        result.insert(key(s.slave, s.name), registers);
    }
    return result;
}

} // namespace opentop::faultmatrix
