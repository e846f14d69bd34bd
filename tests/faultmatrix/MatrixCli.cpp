#include "tests/faultmatrix/MatrixCli.h"

#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QProcess>

namespace opentop::faultmatrix {

QJsonObject CliRun::json() const
{
    return QJsonDocument::fromJson(out.toUtf8()).object();
}

QString CliRun::reason() const
{
    QStringList lines;
    for (const QString& line : err.split(QLatin1Char('\n'), Qt::SkipEmptyParts)) {
        if (line.startsWith(QLatin1String("error:")) ||
            line.startsWith(QLatin1String("interrupted")))
            lines << line.trimmed();
    }
    if (lines.isEmpty()) {
        // --json reports carry the reason per drive.
        for (const QJsonValue& d : json().value(QStringLiteral("drives")).toArray()) {
            const QString r = d.toObject().value(QStringLiteral("reason")).toString();
            if (!r.isEmpty() && !lines.contains(r))
                lines << r;
        }
        for (const QJsonValue& e : json().value(QStringLiteral("errors")).toArray())
            lines << e.toString();
    }
    return lines.join(QStringLiteral("; "));
}

MatrixCli::MatrixCli(const QString& binDir, const QString& port, const QString& variants,
                     const QString& busDrives, int baud)
    : m_binDir(binDir)
    , m_port(port)
    , m_variants(variants)
    , m_busDrives(busDrives)
    , m_baud(baud)
{
}

QStringList MatrixCli::arguments(const QStringList& command) const
{
    QStringList args{QStringLiteral("--port"), m_port, QStringLiteral("--baud"),
                     QString::number(m_baud)};
    if (!m_variants.isEmpty())
        args << QStringLiteral("--variant") << m_variants;
    if (!m_busDrives.isEmpty())
        args << QStringLiteral("--bus-drives") << m_busDrives;
    return args + command;
}

CliRun MatrixCli::run(const QStringList& command, int timeoutMs) const
{
    return runWatching(command, {}, timeoutMs);
}

CliRun MatrixCli::runWatching(const QStringList& command,
                              const std::function<bool(const QString&)>& onTrace,
                              int timeoutMs) const
{
    CliRun r;
    r.arguments =
        arguments(onTrace || m_trace ? command + QStringList{QStringLiteral("--trace")} : command);
    QProcess process;
    QElapsedTimer timer;
    timer.start();
    process.start(m_binDir + QStringLiteral("/opentop-cli"), r.arguments);
    if (!process.waitForStarted(5000)) {
        r.err = QStringLiteral("<cannot start opentop-cli: %1>").arg(process.errorString());
        return r;
    }
    bool watching = bool(onTrace);
    QByteArray out;
    QByteArray err;
    while (process.state() != QProcess::NotRunning && timer.elapsed() < timeoutMs) {
        process.waitForReadyRead(watching ? 5 : 100);
        out += process.readAllStandardOutput();
        const QByteArray more = process.readAllStandardError();
        err += more;
        if (watching && !more.isEmpty() && onTrace(QString::fromUtf8(err)))
            watching = false;
    }
    if (process.state() != QProcess::NotRunning) {
        process.kill();
        process.waitForFinished(2000);
        err += "\n<killed: no end after " + QByteArray::number(timeoutMs) + " ms>";
    } else if (process.exitStatus() == QProcess::NormalExit) {
        r.code = process.exitCode();
    }
    out += process.readAllStandardOutput();
    err += process.readAllStandardError();
    r.out = QString::fromUtf8(out);
    r.err = QString::fromUtf8(err);
    r.ms = timer.elapsed();
    return r;
}

QString MatrixCli::describe(const CliRun& run)
{
    return QStringLiteral("opentop-cli %1\n  exit %2 after %3 ms\n%4%5")
        .arg(run.arguments.join(QLatin1Char(' ')))
        .arg(run.code)
        .arg(run.ms)
        .arg(run.out.left(4000), run.err.left(4000));
}

} // namespace opentop::faultmatrix
