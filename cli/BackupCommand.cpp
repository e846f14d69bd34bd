#include "cli/BackupCommand.h"

#include "cli/CliContext.h"
#include "cli/ExitCode.h"
#include "cli/FileCommandSupport.h"
#include "model/bus/BusScanner.h"
#include "model/files/BackupFile.h"
#include "model/files/DriveBatchReader.h"
#include "model/io/DisplayText.h"
#include "model/io/OutputFile.h"
#include "model/profile/ProfileRegistry.h"
#include "transport/ModbusClient.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QJsonArray>
#include <QTimer>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::BackupCommand", text);
}

QString trn(const char* text, int n)
{
    return QCoreApplication::translate("opentop::BackupCommand", text, nullptr, n);
}

} // namespace

QString BackupCommand::summary() const
{
    return tr("Save every setting of drives to a backup file (written only when all were read)");
}

QList<QCommandLineOption> BackupCommand::options() const
{
    return {{{QStringLiteral("o"), QStringLiteral("output")},
             tr("The backup file to write (replaced atomically)."),
             tr("FILE")},
            {QStringLiteral("all"),
             tr("Every drive the connection knows (a simulated bus), or every drive a scan "
                "finds.")}};
}

std::optional<QVector<int>> BackupCommand::selectIds(CliContext& context, const QStringList& args)
{
    const bool all = context.parser().isSet(QStringLiteral("all"));
    if (all == !args.isEmpty()) {
        context.err() << tr("error: name the machine numbers, or give --all: backup ID... -o FILE")
                      << Qt::endl;
        return std::nullopt;
    }
    if (all)
        return QVector<int>();
    QString error;
    const auto ids = CliContext::parseIds(args.join(QLatin1Char(',')), &error);
    if (!ids)
        context.err() << tr("error: %1").arg(DisplayText::escapedLines(error)) << Qt::endl;
    return ids;
}

QVector<int> BackupCommand::allDrives(CliContext& context, bool* interrupted)
{
    if (!context.knownSlaves().isEmpty())
        return context.knownSlaves();
    if (!context.json())
        context.err() << tr("scanning the bus for drives…") << Qt::endl;
    BusScanner scanner(context.client(), ProfileRegistry::builtIn());
    scanner.setRange(1, 247);
    const bool completed = context.wait([&scanner](std::function<void()> finish) {
        QObject::connect(&scanner, &BusScanner::finished, &scanner, [finish] { finish(); });
        scanner.start();
    });
    if (!completed)
        scanner.cancel();
    *interrupted = !completed || scanner.wasCancelled();
    QVector<int> ids;
    for (const DeviceInfo& info : scanner.devices()) {
        if (info.state == DeviceInfo::State::Present)
            ids << info.slave;
        else if (info.state == DeviceInfo::State::IdentifyFailed)
            context.err() << tr("warning: machine number %1 answered, but its identification "
                                "failed: it is not backed up; name it to try again (backup %1 "
                                "-o FILE).")
                                 .arg(info.slave)
                          << Qt::endl;
    }
    return ids;
}

int BackupCommand::portLost(CliContext& context, const QString& path, const QString& drive,
                            const QStringList& failures)
{
    // The port went away (an adapter pulled out): one line says so and why, instead of one
    // per setting and drive that could no longer be asked.
    QString reason = failures.value(0);
    for (const QString& f : failures) {
        if (f.contains(QLatin1String("port error"))) {
            reason = f;
            break;
        }
    }
    context.err() << tr("error: the port %1 was lost while reading %2 (%3)")
                         .arg(DisplayText::escaped(context.settings().port), drive,
                              DisplayText::escapedLines(reason))
                  << Qt::endl;
    context.err() << tr("nothing written to %1").arg(DisplayText::escaped(path)) << Qt::endl;
    return ExitCommunication;
}

int BackupCommand::run(CliContext& context, const QStringList& args)
{
    const QString path = context.parser().value(QStringLiteral("o"));
    if (path.isEmpty()) {
        context.err() << tr("error: give the file to write: backup ID... -o FILE") << Qt::endl;
        return ExitUsage;
    }
    if (const QString problem = OutputFile::problem(path); !problem.isEmpty()) {
        context.err() << tr("error: %1; nothing read").arg(problem) << Qt::endl;
        return ExitUsage;
    }
    std::optional<QVector<int>> ids = selectIds(context, args);
    if (!ids)
        return ExitUsage;
    if (!context.connectBus())
        return ExitCommunication;
    if (ids->isEmpty()) {
        bool interrupted = false;
        *ids = allDrives(context, &interrupted);
        if (interrupted) {
            context.err() << tr("interrupted: nothing written") << Qt::endl;
            return ExitInterrupted;
        }
        if (ids->isEmpty()) {
            context.err() << tr("error: no drive answers on %1; nothing written")
                                 .arg(context.settings().describe())
                          << Qt::endl;
            return ExitCommunication;
        }
    }

    BackupFile file;
    file.tool = BackupFile::toolName();
    file.created = QDateTime::currentDateTimeUtc();
    file.connection = BackupFile::connectionOf(context.settings());
    QStringList failures;
    bool communication = false;
    QJsonArray drives;
    DriveBatchReader reader(
        [&context](int id, QString* error) { return context.session(id, error); });
    bool lost = false; // the port went away: the rest is not read
    QString lostAt;
    QStringList lostWhy;
    QObject::connect(
        &reader, &DriveBatchReader::driveFinished, &reader,
        [&](const DriveBatchReader::Drive& drive) {
            if (!drive.attempted)
                return;
            const BackupReader::Result& result = drive.read;
            const QString title = drive.error.isEmpty() ? result.device.title()
                                                        : tr("machine number %1").arg(drive.slave);
            if (!drive.ok() && !context.client()->isOpen()) {
                lost = true;
                lostAt = title;
                lostWhy = drive.error.isEmpty() ? result.failures : QStringList{drive.error};
                reader.cancel();
                return;
            }
            failures << drive.problems();
            communication = communication || !drive.error.isEmpty() || !result.failures.isEmpty();
            if (!drive.error.isEmpty())
                return;
            drives << QJsonObject{{QStringLiteral("slave"), drive.slave},
                                  {QStringLiteral("family"), result.device.family},
                                  {QStringLiteral("variant"), result.device.variant},
                                  {QStringLiteral("model"), result.device.model},
                                  {QStringLiteral("parameters"), result.parameters},
                                  {QStringLiteral("read"), int(result.device.parameters.size())},
                                  {QStringLiteral("requests"), result.requests},
                                  {QStringLiteral("elapsedMs"), result.elapsedMs},
                                  {QStringLiteral("ok"), result.ok}};
            if (!context.json() && result.failures.isEmpty())
                context.out() << tr("%1: %2 settings read in %3 requests, %4 ms")
                                     .arg(title)
                                     .arg(result.parameters)
                                     .arg(result.requests)
                                     .arg(result.elapsedMs)
                              << Qt::endl;
            else if (!context.json())
                context.out()
                    << tr("%1: reading failed, %2 of %3 settings read (%4 requests, %5 ms)")
                           .arg(title)
                           .arg(result.device.parameters.size())
                           .arg(result.parameters)
                           .arg(result.requests)
                           .arg(result.elapsedMs)
                    << Qt::endl;
            if (result.ok)
                file.devices << result.device;
        });
    // Ctrl-C stops after the drive being read (a half-read drive is worth nothing).
    bool interrupted = false;
    int current = 0;
    QObject::connect(&reader, &DriveBatchReader::driveStarted, &reader,
                     [&current](int slave, int, int) { current = slave; });
    QEventLoop loop;
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, &loop, [&] {
        if (context.interrupted() && !interrupted) {
            interrupted = true;
            reader.cancel();
        }
    });
    poll.start(50);
    reader.start(*ids, {}, [&loop](const QVector<DriveBatchReader::Drive>&) { loop.quit(); });
    loop.exec();
    if (lost)
        return portLost(context, path, lostAt, lostWhy);
    if (interrupted) {
        context.err()
            << tr("interrupted while reading machine number %1: nothing written").arg(current)
            << Qt::endl;
        return ExitInterrupted;
    }

    QString saveError;
    const bool written =
        failures.isEmpty() && file.save(path, ProfileRegistry::builtIn(), &saveError);
    if (context.json()) {
        FileCommandSupport::printJson(
            context, {{QStringLiteral("command"), QStringLiteral("backup")},
                      {QStringLiteral("file"), path},
                      {QStringLiteral("written"), written},
                      {QStringLiteral("drives"), drives},
                      {QStringLiteral("errors"),
                       QJsonArray::fromStringList(saveError.isEmpty() ? failures
                                                                      : QStringList{saveError})}});
    }
    for (const QString& f : failures)
        context.err() << tr("error: %1").arg(DisplayText::escapedLines(f)) << Qt::endl;
    if (!failures.isEmpty()) {
        context.err() << tr("nothing written to %1").arg(DisplayText::escaped(path)) << Qt::endl;
        return communication ? ExitCommunication : ExitInvalid;
    }
    if (!written) {
        context.err() << tr("error: %1").arg(DisplayText::escapedLines(saveError)) << Qt::endl;
        return ExitUsage;
    }
    if (!context.json())
        context.out() << trn("wrote %1: %n drive(s)", int(file.devices.size()))
                             .arg(DisplayText::escaped(path))
                      << Qt::endl;
    return ExitOk;
}

} // namespace opentop
