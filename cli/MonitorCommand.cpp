#include "cli/MonitorCommand.h"

#include "cli/CliContext.h"
#include "cli/MonitorCsv.h"
#include "cli/MonitorOutput.h"
#include "model/bus/BusMemory.h"
#include "model/bus/LinkRecovery.h"
#include "model/monitor/DeviceMonitor.h"
#include "model/session/DeviceSession.h"
#include "transport/ModbusClient.h"

#include <QCoreApplication>
#include <QJsonDocument>
#include <algorithm>
#include <memory>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::MonitorCommand", text);
}

constexpr int kMinInterval = 50;
constexpr int kMaxInterval = 60000;
constexpr double kMaxGiveUpSeconds = 86400;

QString seconds(qint64 ms)
{
    return QString::number(double(ms) / 1000.0, 'f', 1);
}

// One monitored drive.
struct Watched
{
    std::unique_ptr<DeviceMonitor> monitor;
    std::unique_ptr<MonitorOutput> output;
    int polls = 0;
};

} // namespace

QString MonitorCommand::summary() const
{
    return tr("Watch speed, load, state, inputs and alarms live (Ctrl-C ends)");
}

QList<QCommandLineOption> MonitorCommand::options() const
{
    return {
        {QStringLiteral("interval"),
         tr("Time between samples of a drive in ms, %1–%2 (default 500).")
             .arg(kMinInterval)
             .arg(kMaxInterval),
         tr("MS")},
        {QStringLiteral("count"), tr("Stop after N samples per drive (default: until Ctrl-C)."),
         tr("N")},
        {QStringLiteral("csv"),
         tr("Also write every sample to FILE (CSV with a header; a row with a note where the "
            "link was lost and where it came back)."),
         tr("FILE")},
        {QStringLiteral("give-up"),
         tr("When the link to the bus is lost, exit 1 if it is not back within SECONDS "
            "(default: reconnect by itself, 0.5 s to 5 s apart, until Ctrl-C)."),
         tr("SECONDS")},
    };
}

int MonitorCommand::run(CliContext& context, const QStringList& args)
{
    QTextStream& err = context.err();
    const QCommandLineParser& parser = context.parser();
    QString error;
    const auto ids =
        args.isEmpty() ? std::nullopt : CliContext::parseIds(args.join(QLatin1Char(',')), &error);
    if (!ids) {
        err << tr("error: usage: %1").arg(synopsis())
            << (error.isEmpty() ? QString() : QStringLiteral(" (") + error + QLatin1Char(')'))
            << Qt::endl;
        return ExitUsage;
    }
    int interval = 500;
    if (parser.isSet(QStringLiteral("interval"))) {
        bool ok = false;
        interval = parser.value(QStringLiteral("interval")).toInt(&ok);
        if (!ok || interval < kMinInterval || interval > kMaxInterval) {
            err << tr("error: --interval must be %1–%2 ms, got \"%3\"")
                       .arg(kMinInterval)
                       .arg(kMaxInterval)
                       .arg(parser.value(QStringLiteral("interval")))
                << Qt::endl;
            return ExitUsage;
        }
    }
    int count = 0; // 0: until Ctrl-C
    if (parser.isSet(QStringLiteral("count"))) {
        bool ok = false;
        count = parser.value(QStringLiteral("count")).toInt(&ok);
        if (!ok || count < 1) {
            err << tr("error: --count must be a whole number of samples, 1 or more, got \"%1\"")
                       .arg(parser.value(QStringLiteral("count")))
                << Qt::endl;
            return ExitUsage;
        }
    }
    qint64 giveUpMs = 0; // 0: reconnect until Ctrl-C
    if (parser.isSet(QStringLiteral("give-up"))) {
        bool ok = false;
        const double value = parser.value(QStringLiteral("give-up")).toDouble(&ok);
        if (!ok || !(value > 0) || value > kMaxGiveUpSeconds) {
            err << tr("error: --give-up must be a number of seconds, more than 0 and at most "
                      "%1, got \"%2\"")
                       .arg(kMaxGiveUpSeconds)
                       .arg(parser.value(QStringLiteral("give-up")))
                << Qt::endl;
            return ExitUsage;
        }
        giveUpMs = std::max<qint64>(1, qint64(value * 1000));
    }
    MonitorCsv csv;
    if (parser.isSet(QStringLiteral("csv"))) {
        if (!csv.open(parser.value(QStringLiteral("csv")), &error)) {
            err << tr("error: cannot write %1: %2").arg(csv.fileName(), error) << Qt::endl;
            return ExitInvalid;
        }
    }

    std::vector<Watched> watched;
    for (int id : *ids) {
        DeviceSession* session = context.session(id, &error);
        if (!session) {
            err << tr("error: %1").arg(error) << Qt::endl;
            return ExitCommunication;
        }
        Watched w;
        w.monitor = std::make_unique<DeviceMonitor>(session);
        w.monitor->setInterval(interval);
        watched.push_back(std::move(w));
    }
    // The display settings first: they decide the display columns.
    for (Watched& w : watched) {
        QString problem;
        const bool done = context.wait([&](std::function<void()> finish) {
            w.monitor->prepare([&problem, finish](const QString& e) {
                problem = e;
                finish();
            });
        });
        if (!done)
            return ExitInterrupted;
        if (!problem.isEmpty())
            err << tr("warning: machine number %1: %2; speeds are shown in r/min only")
                       .arg(w.monitor->session()->slave())
                       .arg(problem)
                << Qt::endl;
        w.output = std::make_unique<MonitorOutput>(*w.monitor);
    }

    if (csv.isOpen()) {
        std::vector<const MonitorOutput*> outputs;
        for (const Watched& w : watched)
            outputs.push_back(w.output.get());
        csv.writeHeader(outputs); // a failure shows at the first sample's row
    }
    QTextStream& out = context.out();
    if (!context.json()) {
        QStringList printed;
        for (const Watched& w : watched) {
            if (printed.contains(w.output->family()))
                continue;
            printed << w.output->family();
            out << w.output->headerLine() << '\n';
        }
        out.flush();
    }

    int errors = 0;
    bool csvFailed = false;
    bool gaveUp = false;
    std::function<void()> finishAll;
    auto stopAll = [&] {
        for (Watched& x : watched)
            x.monitor->stop();
        if (finishAll)
            finishAll();
    };
    // A full disk or device: say so and stop, never keep "recording".
    auto csvWritten = [&](bool ok) {
        if (ok || csvFailed)
            return ok;
        csvFailed = true;
        err << tr("error: cannot write %1: %2; monitoring stopped")
                   .arg(csv.fileName(), csv.errorString())
            << Qt::endl;
        stopAll();
        return false;
    };
    auto countPoll = [&](Watched& w) {
        ++w.polls;
        if (count == 0)
            return;
        if (w.polls >= count)
            w.monitor->stop();
        bool all = true;
        for (const Watched& x : watched)
            all = all && x.polls >= count;
        if (all && finishAll)
            finishAll();
    };

    // A lost port is said once and opened again by itself; nothing is polled meanwhile, so
    // nothing is printed every interval. Once it is back the drives are polled again.
    const QString place = BusMemory::placeText(context.settings());
    LinkRecovery recovery(context.client());
    recovery.setGiveUpMs(giveUpMs);
    auto linkJson = [&](const QDateTime& at, const QString& link, QJsonObject o) {
        if (!context.json())
            return;
        o.insert(QStringLiteral("timestamp"), MonitorOutput::isoTime(at));
        o.insert(QStringLiteral("link"), link);
        o.insert(QStringLiteral("port"), place);
        out << QJsonDocument(o).toJson(QJsonDocument::Compact) << '\n';
        out.flush();
    };
    QObject::connect(
        &recovery, &LinkRecovery::lost, &context, [&](const QDateTime& at, const QString& why) {
            for (Watched& w : watched)
                w.monitor->stop(); // the poll under way is dropped: its error is this one
            const QString time = MonitorOutput::isoTime(at);
            if (giveUpMs > 0)
                err << tr("%1 link lost: %2 (%3); reconnecting for up to %4 s (Ctrl-C ends)")
                           .arg(time, place, why, seconds(giveUpMs))
                    << Qt::endl;
            else
                err << tr("%1 link lost: %2 (%3); reconnecting until it is back (Ctrl-C ends)")
                           .arg(time, place, why)
                    << Qt::endl;
            linkJson(at, QStringLiteral("lost"), {{QStringLiteral("error"), why}});
            if (csv.isOpen())
                csvWritten(csv.writeNote(at, MonitorCsv::linkLostNote()));
        });
    QObject::connect(&recovery, &LinkRecovery::back, &context, [&](qint64 lostMs) {
        const QDateTime now = QDateTime::currentDateTime();
        err << tr("%1 link back after %2 s: %3; monitoring goes on")
                   .arg(MonitorOutput::isoTime(now), seconds(lostMs), place)
            << Qt::endl;
        linkJson(now, QStringLiteral("back"),
                 {{QStringLiteral("lostSeconds"), double(lostMs) / 1000.0}});
        if (csv.isOpen() && !csvWritten(csv.writeNote(now, MonitorCsv::linkBackNote())))
            return;
        for (Watched& w : watched) {
            if (count == 0 || w.polls < count)
                w.monitor->start();
        }
    });
    QObject::connect(
        &recovery, &LinkRecovery::gaveUp, &context, [&](qint64 lostMs, const QString& why) {
            gaveUp = true;
            err << tr("error: the link to %1 was lost at %2 and is not back after %3 s "
                      "(--give-up %4): %5; monitoring stopped")
                       .arg(place, recovery.lostAt().toString(QStringLiteral("HH:mm:ss")),
                            seconds(lostMs), parser.value(QStringLiteral("give-up")), why)
                << Qt::endl;
            stopAll();
        });

    for (Watched& w : watched) {
        Watched* wp = &w;
        QObject::connect(
            w.monitor.get(), &DeviceMonitor::sample, &context,
            [&, wp](const QDateTime&, const MonitorSample& s) {
                if (context.json())
                    out << QJsonDocument(wp->output->json(s)).toJson(QJsonDocument::Compact)
                        << '\n';
                else
                    out << wp->output->line(s) << '\n';
                out.flush();
                if (csv.isOpen() && !csvWritten(csv.writeSample(*wp->output, s)))
                    return;
                countPoll(*wp);
            });
        QObject::connect(
            w.monitor.get(), &DeviceMonitor::error, &context, [&, wp](const QString& text) {
                if (recovery.isLost())
                    return; // said once when it was lost
                if (!context.client()->isOpen()) {
                    // Lost before it was watched (while the display settings were read).
                    recovery.markLost(text);
                    return;
                }
                ++errors;
                const QString time = MonitorOutput::isoTime(QDateTime::currentDateTime());
                if (context.json())
                    out << QJsonDocument(QJsonObject{{QStringLiteral("timestamp"), time},
                                                     {QStringLiteral("slave"),
                                                      wp->monitor->session()->slave()},
                                                     {QStringLiteral("error"), text}})
                               .toJson(QJsonDocument::Compact)
                        << '\n';
                else
                    err << tr("%1 error: %2").arg(time, text) << Qt::endl;
                out.flush();
                countPoll(*wp);
            });
    }
    const bool completed = context.wait([&](std::function<void()> finish) {
        finishAll = finish;
        for (Watched& w : watched)
            w.monitor->start();
    });
    finishAll = nullptr;
    recovery.stop();
    for (Watched& w : watched)
        w.monitor->stop();
    out.flush();
    Q_UNUSED(completed) // Ctrl-C is the normal end without --count (exit 130 by CliApp)
    if (csvFailed)
        return ExitUsage; // as a backup file that cannot be written
    if (gaveUp)
        return ExitCommunication;
    return errors > 0 ? ExitCommunication : ExitOk;
}

} // namespace opentop
