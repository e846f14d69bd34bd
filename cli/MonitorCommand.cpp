#include "cli/MonitorCommand.h"

#include "cli/CliContext.h"
#include "cli/MonitorOutput.h"
#include "model/monitor/DeviceMonitor.h"
#include "model/session/DeviceSession.h"

#include <QCoreApplication>
#include <QFile>
#include <QJsonDocument>
#include <memory>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::MonitorCommand", text);
}

constexpr int kMinInterval = 50;
constexpr int kMaxInterval = 60000;

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
        {QStringLiteral("csv"), tr("Also write every sample to FILE (CSV with a header)."),
         tr("FILE")},
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
    QFile csv;
    if (parser.isSet(QStringLiteral("csv"))) {
        csv.setFileName(parser.value(QStringLiteral("csv")));
        if (!csv.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text)) {
            err << tr("error: cannot write %1: %2").arg(csv.fileName(), csv.errorString())
                << Qt::endl;
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

    QTextStream csvOut(&csv);
    QStringList csvKeys;
    if (csv.isOpen()) {
        for (const Watched& w : watched) {
            for (const MonitorOutput::Column& c : w.output->columns()) {
                if (!csvKeys.contains(c.key))
                    csvKeys << c.key;
            }
        }
        QStringList header{QStringLiteral("timestamp"), QStringLiteral("slave"),
                           QStringLiteral("family")};
        for (const QString& k : csvKeys)
            header << MonitorOutput::csvEscape(k);
        csvOut << header.join(QLatin1Char(',')) << '\n';
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
    std::function<void()> finishAll;
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
                if (csv.isOpen()) {
                    const QStringList cells = wp->output->csvCells(s);
                    QStringList row{MonitorOutput::isoTime(s.timestamp), QString::number(s.slave),
                                    wp->output->family()};
                    for (const QString& key : csvKeys) {
                        int column = -1;
                        for (int i = 0; i < wp->output->columns().size(); ++i)
                            column = wp->output->columns()[i].key == key ? i : column;
                        row << MonitorOutput::csvEscape(column >= 0 ? cells.value(column)
                                                                    : QString());
                    }
                    csvOut << row.join(QLatin1Char(',')) << '\n';
                    csvOut.flush();
                    if (!csvFailed && (csvOut.status() != QTextStream::Ok ||
                                       csv.error() != QFileDevice::NoError)) {
                        // A full disk or device: say so and stop, never keep "recording".
                        csvFailed = true;
                        err << tr("error: cannot write %1: %2; monitoring stopped")
                                   .arg(csv.fileName(), csv.errorString())
                            << Qt::endl;
                        for (Watched& x : watched)
                            x.monitor->stop();
                        if (finishAll)
                            finishAll();
                        return;
                    }
                }
                countPoll(*wp);
            });
        QObject::connect(
            w.monitor.get(), &DeviceMonitor::error, &context, [&, wp](const QString& text) {
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
    for (Watched& w : watched)
        w.monitor->stop();
    out.flush();
    Q_UNUSED(completed) // Ctrl-C is the normal end without --count (exit 130 by CliApp)
    if (csvFailed)
        return ExitUsage; // as a backup file that cannot be written
    return errors > 0 ? ExitCommunication : ExitOk;
}

} // namespace opentop
