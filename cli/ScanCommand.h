#pragma once

#include "cli/CliCommand.h"
#include "model/session/DeviceInfo.h"

#include <QHash>
#include <QVector>

namespace opentop {

class BusGroups;
class BusScanner;
class CliContext;

// `scan [--from N] [--to N] [--wait MS]`: finds and identifies the drives on the bus, with
// progress on standard error, a table (or --json) on standard output, and a warning for machine
// numbers that two drives seem to share and for those that answered but could not be identified
// (exit 1: the scan did not find out everything it should).
class ScanCommand : public CliCommand
{
public:
    QString name() const override { return QStringLiteral("scan"); }
    QString synopsis() const override
    {
        return QStringLiteral("scan [--from N] [--to N] [--wait MS] [--try-formats]");
    }
    QString summary() const override;
    QList<QCommandLineOption> options() const override;
    int run(CliContext& context, const QStringList& args) override;

private:
    struct Range
    {
        int from = 1;
        int to = 247;
        int waitMs = 0; // 0: derived from the baud rate
    };
    static bool parseRange(CliContext& context, const QStringList& args, Range* range);
    // What the serial driver accepted (RS-485 direction, low latency), and a warning when the
    // adapter holds replies back.
    static void printLineReport(CliContext& context);
    static void printTable(CliContext& context, const QVector<DeviceInfo>& devices,
                           const BusGroups& groups, const QHash<int, bool>& hasGroups);
    static void printJson(CliContext& context, const BusScanner& scanner,
                          const QVector<DeviceInfo>& devices, bool interrupted,
                          const BusGroups& groups, const QHash<int, bool>& hasGroups);
    static QString summaryLine(const QVector<DeviceInfo>& devices, double elapsedMs);
    static void warnDuplicates(CliContext& context, const QVector<DeviceInfo>& devices);
};

} // namespace opentop
