#pragma once

// Runs the opentop-sim executable for end-to-end tests: waits for "ready", talks to its
// console on stdin/stdout, stops it with SIGTERM.

#include <QProcess>
#include <QRegularExpression>
#include <QStringList>
#include <gtest/gtest.h>
#include <optional>

namespace opentop::test {

class SimProcess
{
public:
    static QString program() { return QStringLiteral(OPENTOP_BIN_DIR "/opentop-sim"); }

    ~SimProcess()
    {
        if (m_process.state() != QProcess::NotRunning) {
            m_process.kill();
            m_process.waitForFinished(2000);
        }
    }

    // Starts the simulator and waits until it prints "ready". `quiet` false: every frame is
    // traced on its stderr ("rx 01 03 ... tx ...").
    bool start(const QStringList& arguments, QString* error = nullptr, bool quiet = true)
    {
        m_process.setProgram(program());
        m_process.setArguments(arguments +
                               (quiet ? QStringList{QStringLiteral("--quiet")} : QStringList()));
        m_process.start();
        if (!m_process.waitForStarted(5000)) {
            if (error)
                *error = m_process.errorString();
            return false;
        }
        for (;;) {
            const std::optional<QString> line = readLine(5000);
            if (!line) {
                if (error)
                    *error = QStringLiteral("no \"ready\": ") +
                             QString::fromLocal8Bit(m_process.readAllStandardError());
                return false;
            }
            if (line->startsWith(QLatin1String("pty: ")))
                pty = line->mid(5);
            else if (line->startsWith(QLatin1String("tcp: ")))
                tcp = line->mid(5);
            else if (*line == QLatin1String("ready"))
                return true;
        }
    }

    std::optional<QString> readLine(int timeoutMs)
    {
        while (!m_process.canReadLine()) {
            if (!m_process.waitForReadyRead(timeoutMs))
                return std::nullopt;
        }
        return QString::fromLocal8Bit(m_process.readLine()).trimmed();
    }

    // One console command with a one-line answer.
    QString command(const QString& line)
    {
        m_process.write((line + QLatin1Char('\n')).toLocal8Bit());
        return readLine(3000).value_or(QStringLiteral("<no answer>"));
    }

    // The value of a register as the simulator holds it ("get ID ADDR [fc]").
    int get(int slave, int address, int function = 0)
    {
        QString line =
            QStringLiteral("get %1 0x%2").arg(slave).arg(address, 4, 16, QLatin1Char('0'));
        if (function)
            line += QStringLiteral(" %1").arg(function);
        const QString answer = command(line);
        static const QRegularExpression value(QStringLiteral(" = (\\d+) "));
        const QRegularExpressionMatch m = value.match(answer);
        EXPECT_TRUE(m.hasMatch()) << answer.toStdString();
        return m.hasMatch() ? m.captured(1).toInt() : -1;
    }

    // Sends SIGTERM and returns the exit code (-1 when it did not exit normally).
    int terminate()
    {
        m_process.terminate();
        if (!m_process.waitForFinished(5000))
            return -1;
        return m_process.exitStatus() == QProcess::NormalExit ? m_process.exitCode() : -1;
    }

    QProcess& process() { return m_process; }

    QString pty;
    QString tcp;

private:
    QProcess m_process;
};

} // namespace opentop::test
