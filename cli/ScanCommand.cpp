#include "cli/ScanCommand.h"

#include "cli/CliContext.h"
#include "cli/GroupCheck.h"
#include "cli/ScanDrives.h"
#include "cli/ScanFormats.h"
#include "cli/ScanProgress.h"
#include "cli/TextTable.h"
#include "model/bus/BusGroups.h"
#include "model/bus/BusMemory.h"
#include "model/bus/BusScanner.h"
#include "model/bus/FixedLineHint.h"
#include "model/profile/ProfileRegistry.h"
#include "transport/ModbusClient.h"

#include <QCoreApplication>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <algorithm>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::ScanCommand", text);
}

QString seconds(double ms)
{
    return QString::number(ms / 1000.0, 'f', 1);
}

QString stateId(DeviceInfo::State state)
{
    switch (state) {
    case DeviceInfo::State::Present:
        return QStringLiteral("present");
    case DeviceInfo::State::Absent:
        return QStringLiteral("absent");
    case DeviceInfo::State::Garbled:
        return QStringLiteral("garbled");
    case DeviceInfo::State::Unidentified:
        return QStringLiteral("unidentified");
    case DeviceInfo::State::IdentifyFailed:
        return QStringLiteral("identification-failed");
    case DeviceInfo::State::Unknown:
        break;
    }
    return QStringLiteral("unknown");
}

bool isDrive(const DeviceInfo& info)
{
    return info.state == DeviceInfo::State::Present ||
           info.state == DeviceInfo::State::Unidentified;
}

} // namespace

QString ScanCommand::summary() const
{
    return tr("Find and identify the drives on the bus (machine numbers 1–247)");
}

QList<QCommandLineOption> ScanCommand::options() const
{
    return {
        {QStringLiteral("from"), tr("First machine number to ask, 1–247 (default 1)."), tr("N")},
        {QStringLiteral("to"), tr("Last machine number to ask, 1–247 (default 247)."), tr("N")},
        {QStringLiteral("wait"),
         tr("Wait per machine number in ms, 10–5000 (default: derived from the baud rate; "
            "raise it for slow adapters or gateways)."),
         tr("MS")},
        {QStringLiteral("try-formats"),
         tr("Also ask the machine numbers not found in every other line format a drive can be "
            "set to (a DC controller at 8E1 on a DBU bus at 8N1): one more pass per format, "
            "off by default.")},
    };
}

bool ScanCommand::parseRange(CliContext& context, const QStringList& args, Range* range)
{
    const QCommandLineParser& p = context.parser();
    auto number = [&](const QString& option, int min, int max, int* target) {
        if (!p.isSet(option))
            return true;
        bool ok = false;
        const int value = p.value(option).toInt(&ok);
        if (!ok || value < min || value > max) {
            context.err() << tr("error: --%1 must be a number %2–%3, not \"%4\"")
                                 .arg(option)
                                 .arg(min)
                                 .arg(max)
                                 .arg(p.value(option))
                          << Qt::endl;
            return false;
        }
        *target = value;
        return true;
    };
    if (!args.isEmpty()) {
        context.err() << tr("error: scan takes no arguments; use --from N --to N") << Qt::endl;
        return false;
    }
    if (!number(QStringLiteral("from"), 1, 247, &range->from) ||
        !number(QStringLiteral("to"), 1, 247, &range->to) ||
        !number(QStringLiteral("wait"), BusScanner::kMinWaitMs, BusScanner::kMaxWaitMs,
                &range->waitMs))
        return false;
    if (range->from > range->to) {
        context.err() << tr("error: --from %1 is after --to %2").arg(range->from).arg(range->to)
                      << Qt::endl;
        return false;
    }
    return true;
}

int ScanCommand::run(CliContext& context, const QStringList& args)
{
    Range range;
    if (!parseRange(context, args, &range))
        return ExitUsage;
    if (!context.connectBus())
        return ExitCommunication;

    BusScanner scanner(context.client(), ProfileRegistry::builtIn());
    scanner.setRange(range.from, range.to);
    scanner.setWaitMs(range.waitMs);
    context.err() << tr("Scanning machine numbers %1–%2 on %3, %4 ms each…")
                         .arg(range.from)
                         .arg(range.to)
                         .arg(context.client()->describe())
                         .arg(scanner.waitMs())
                  << Qt::endl;
    printLineReport(context);
    ScanProgress progress(context.err());
    QObject::connect(&scanner, &BusScanner::found, &scanner, [&progress](const DeviceInfo& info) {
        if (isDrive(info))
            progress.deviceFound();
    });
    QObject::connect(
        &scanner, &BusScanner::progress, &scanner,
        [&progress](int done, int total, int slave) { progress.update(done, total, slave); });
    QObject::connect(&scanner, &BusScanner::identificationRetry, &scanner,
                     [&progress](int slave, int attempt, int attempts) {
                         progress.identificationRetry(slave, attempt, attempts);
                     });
    const bool completed = context.wait([&scanner](std::function<void()> finish) {
        QObject::connect(&scanner, &BusScanner::finished, &scanner, [finish] { finish(); });
        scanner.start();
    });
    if (!completed)
        scanner.cancel(); // Ctrl-C: the event loop has stopped, nothing more is asked
    progress.clear();
    bool interrupted = !completed || (scanner.wasCancelled() && context.interrupted());

    QVector<DeviceInfo> devices = scanner.devices();
    double elapsedMs = scanner.elapsedMs();
    const bool tryFormats = context.parser().isSet(QStringLiteral("try-formats"));
    if (!interrupted && scanner.error().isEmpty() && tryFormats &&
        !ScanFormats::run(context, range.from, range.to, range.waitMs, &devices, &elapsedMs))
        interrupted = true;
    ScanDrives::complete(context, &devices);
    BusGroups groups;
    QHash<int, bool> hasGroups;
    if (!interrupted)
        GroupCheck::readAll(context, devices, &groups, &hasGroups);
    if (context.json())
        printJson(context, scanner, devices, interrupted, groups, hasGroups);
    else if (!devices.isEmpty())
        printTable(context, devices, groups, hasGroups);

    const int scanned = scanner.scannedCount();
    if (interrupted) {
        if (scanned == 0)
            context.err() << tr("Interrupted before any machine number was scanned.") << Qt::endl;
        else
            context.err() << tr("Interrupted: machine numbers %1–%2 were scanned (%3 of %4); "
                                "%5–%6 were not asked.")
                                 .arg(range.from)
                                 .arg(range.from + scanned - 1)
                                 .arg(scanned)
                                 .arg(scanner.total())
                                 .arg(range.from + scanned)
                                 .arg(range.to)
                          << Qt::endl;
        if (!context.json())
            context.out() << summaryLine(devices, elapsedMs) << Qt::endl;
        return ExitInterrupted;
    }
    if (!scanner.error().isEmpty()) {
        context.err() << tr("error: the scan stopped at machine number %1: %2")
                             .arg(range.from + scanned)
                             .arg(scanner.error())
                      << Qt::endl;
        return ExitCommunication;
    }
    // The drives found are this connection's from now on (shared with the window): a later
    // write or command reads their communication groups to name every drive it reaches.
    const QString key = BusMemory::key(context.settings());
    BusMemory::update(key, range.from, range.to, BusMemory::present(devices));
    if (!context.json())
        context.out() << summaryLine(devices, elapsedMs) << Qt::endl;
    context.err() << tr("note: remembered for %1: %2; set, run and restore read their "
                        "communication groups before a write")
                         .arg(BusMemory::placeText(context.settings()),
                              BusMemory::listText(BusMemory::load(key)))
                  << Qt::endl;
    warnDuplicates(context, devices);
    if (!tryFormats)
        ScanFormats::hint(context, range.from, range.to, devices);
    for (const BusGroups::Problem& problem : groups.problems())
        context.err() << tr("warning: %1").arg(BusGroups::describe(problem)) << Qt::endl;
    if (scanner.lateAnswers() > 0)
        context.err() << tr("note: %1 drive(s) answered only after the %2 ms wait and were asked "
                            "again; if scans miss drives, give a longer --wait.")
                             .arg(scanner.lateAnswers())
                             .arg(scanner.waitMs())
                      << Qt::endl;
    // Something answered there but never said what it is: reported, and the scan did not do
    // all it should (exit 1).
    const QVector<int> unidentified = BusScanner::unidentified(devices);
    for (int slave : unidentified)
        context.err() << tr("warning: machine number %1 answered, but its identification failed, "
                            "also when asked again %2 more times; it is not counted as a drive. "
                            "Add it by hand: name it in a command (it is identified again then, "
                            "within --timeout; raise it for a slow device), or check its line "
                            "settings and scan again with a longer --wait.")
                             .arg(slave)
                             .arg(BusScanner::kIdentifyRetries)
                      << Qt::endl;
    if (devices.isEmpty()) {
        context.err() << tr("No drive answered at machine numbers %1–%2. Check:\n"
                            "  - the wiring, and the A/B polarity (swap A and B if unsure);\n"
                            "  - baud rate and parity: the drives' settings must match %3 "
                            "(--baud, --parity, --family);\n"
                            "  - the termination (120 Ω at both ends of the bus) and that the "
                            "drives are powered.")
                             .arg(range.from)
                             .arg(range.to)
                             .arg(context.client()->describe())
                      << Qt::endl;
        // A DC controller in potentiometer/analog control ignores its configured line settings.
        const FixedLineHint fixed = FixedLineHint::dcPotentiometer();
        if (fixed.worthRetrying(context.client()->settings(), range.from, range.to))
            context.err() << tr("hint: %1 Retry with the same connection and: %2")
                                 .arg(fixed.explanation(), fixed.commandLine())
                          << Qt::endl;
        return ExitCommunication;
    }
    return unidentified.isEmpty() ? ExitOk : ExitCommunication;
}

void ScanCommand::printLineReport(CliContext& context)
{
    const SerialLineReport report = context.client()->lineReport();
    if (report.isEmpty())
        return;
    context.err() << tr("Serial line: %1").arg(report.text()) << Qt::endl;
    const QString warning = report.latencyWarning();
    if (!warning.isEmpty())
        context.err() << tr("warning: %1 The scan waits up to %2 ms longer per machine number "
                            "because of it.")
                             .arg(warning)
                             .arg(report.adapterLatencyMs())
                      << Qt::endl;
}

void ScanCommand::printTable(CliContext& context, const QVector<DeviceInfo>& devices,
                             const BusGroups& groups, const QHash<int, bool>& hasGroups)
{
    QStringList headers{tr("ID"),    tr("hex"),      tr("switches"), tr("family"),
                        tr("model"), tr("firmware"), tr("state")};
    // Only where a machine has a name: a column of blanks would say nothing.
    const bool showNames = std::any_of(devices.begin(), devices.end(), [](const DeviceInfo& d) {
        return !d.machineName.isEmpty();
    });
    if (showNames)
        headers.insert(1, tr("name"));
    // Only where a group is in use: a column of "off" would say nothing.
    bool showGroups = false;
    for (int slave : groups.drives())
        showGroups = showGroups || (hasGroups.value(slave) && groups.groupOf(slave));
    if (showGroups)
        headers << tr("comm. group");
    // Only where a drive talks another format than the port's.
    const bool showLine = std::any_of(devices.begin(), devices.end(),
                                      [](const DeviceInfo& d) { return d.line.isSet(); });
    if (showLine)
        headers << tr("line format");
    TextTable table(headers);
    table.setRightAligned(0);
    table.setRightAligned(showNames ? 2 : 1); // hex
    for (const DeviceInfo& info : devices) {
        QStringList row{QString::number(info.slave),
                        DeviceInfo::hexText(info.slave),
                        DeviceInfo::switchText(info.slave, info.family),
                        info.family,
                        info.model,
                        info.firmware.isEmpty() ? QString() : QStringLiteral("V") + info.firmware,
                        DeviceInfo::stateText(info.state)};
        if (showNames)
            row.insert(1, info.machineName);
        if (showGroups)
            row << GroupCheck::groupText(groups, hasGroups, info.slave);
        if (showLine)
            row << (info.line.isSet() ? info.line.text() : tr("the port's"));
        table.addRow(row);
    }
    table.print(context.out());
}

void ScanCommand::printJson(CliContext& context, const BusScanner& scanner,
                            const QVector<DeviceInfo>& devices, bool interrupted,
                            const BusGroups& groups, const QHash<int, bool>& hasGroups)
{
    QJsonArray list;
    for (const DeviceInfo& info : devices) {
        QJsonObject device{
            {QStringLiteral("slave"), info.slave},
            {QStringLiteral("hex"), DeviceInfo::hexText(info.slave)},
            {QStringLiteral("switches"), DeviceInfo::switchText(info.slave, info.family)},
            {QStringLiteral("family"), info.family},
            {QStringLiteral("variant"), info.variant},
            {QStringLiteral("model"), info.model},
            {QStringLiteral("firmware"), info.firmware},
            {QStringLiteral("state"), stateId(info.state)},
            {QStringLiteral("detail"), info.detail},
            {QStringLiteral("name"), info.machineName},
            {QStringLiteral("line"), info.line.isSet() ? info.line.token() : QString()},
        };
        GroupCheck::addJson(groups, hasGroups, info.slave, &device);
        list.append(device);
    }
    QJsonArray problems;
    for (const BusGroups::Problem& problem : groups.problems())
        problems.append(BusGroups::describe(problem));
    QJsonObject scan{
        {QStringLiteral("from"), scanner.from()},
        {QStringLiteral("to"), scanner.to()},
        {QStringLiteral("waitMs"), scanner.waitMs()},
        {QStringLiteral("elapsedMs"), qRound(scanner.elapsedMs())},
        {QStringLiteral("devices"), list},
    };
    if (!problems.isEmpty())
        scan.insert(QStringLiteral("groupProblems"), problems);
    if (interrupted) {
        scan.insert(QStringLiteral("interrupted"), true);
        scan.insert(QStringLiteral("scannedTo"), scanner.from() + scanner.scannedCount() - 1);
    }
    context.out() << QJsonDocument(QJsonObject{{QStringLiteral("scan"), scan}}).toJson();
}

QString ScanCommand::summaryLine(const QVector<DeviceInfo>& devices, double elapsedMs)
{
    int drives = 0;
    QStringList duplicates;
    QStringList unidentified;
    for (const DeviceInfo& info : devices) {
        drives += isDrive(info) ? 1 : 0;
        if (info.state == DeviceInfo::State::Garbled)
            duplicates << QString::number(info.slave);
        if (info.state == DeviceInfo::State::IdentifyFailed)
            unidentified << QString::number(info.slave);
    }
    // Whole sentences per number, so that translators get complete phrases.
    QString line = drives == 1 ? tr("1 drive found in %1 s").arg(seconds(elapsedMs))
                               : tr("%1 drives found in %2 s").arg(drives).arg(seconds(elapsedMs));
    if (duplicates.size() == 1)
        line += tr("; 1 possible duplicate machine number: %1").arg(duplicates.first());
    else if (duplicates.size() > 1)
        line += tr("; %1 possible duplicate machine numbers: %2")
                    .arg(duplicates.size())
                    .arg(duplicates.join(QStringLiteral(", ")));
    if (!unidentified.isEmpty())
        line += tr("; answered, identification failed: %1 (add by hand)")
                    .arg(unidentified.join(QStringLiteral(", ")));
    return line;
}

void ScanCommand::warnDuplicates(CliContext& context, const QVector<DeviceInfo>& devices)
{
    for (const DeviceInfo& info : devices) {
        if (info.state != DeviceInfo::State::Garbled)
            continue;
        context.err() << tr("warning: machine number %1 (%2) answers with garbled replies: "
                            "two drives probably have the same machine number. Check the address "
                            "switches of the drives on this bus, give each drive its own machine "
                            "number, power them off and on, and scan again.")
                             .arg(info.slave)
                             .arg(DeviceInfo::addressText(info.slave, QString()))
                      << Qt::endl;
    }
}

} // namespace opentop
