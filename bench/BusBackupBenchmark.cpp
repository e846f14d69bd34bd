#include "bench/BusBackupBenchmark.h"

#include "bench/BenchReport.h"
#include "bench/SimulatorProcess.h"
#include "model/profile/ProfileRegistry.h"
#include "model/session/ReadPlanner.h"
#include "sim/WireTiming.h"

#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

namespace opentop {

namespace {

constexpr int kDrives = 32;
constexpr int kBaud = 115200;

struct CliRun
{
    double seconds = 0;
    int requests = 0;
    int drives = 0;
};

bool backup(const BenchEnvironment& env, const QString& pty, const QStringList& which,
            const QString& file, CliRun* run, QString* error)
{
    QProcess cli;
    QElapsedTimer timer;
    timer.start();
    cli.start(env.binDir + QStringLiteral("/opentop-cli"),
              QStringList{QStringLiteral("--port"), pty, QStringLiteral("--baud"),
                          QString::number(kBaud), QStringLiteral("--parity"), QStringLiteral("N"),
                          QStringLiteral("--json"), QStringLiteral("backup")} +
                  which + QStringList{QStringLiteral("-o"), file});
    if (!cli.waitForFinished(120000) || cli.exitCode() != 0) {
        *error = QStringLiteral("opentop-cli backup %1 failed (exit %2): %3")
                     .arg(which.join(QLatin1Char(' ')))
                     .arg(cli.exitCode())
                     .arg(QString::fromLocal8Bit(cli.readAllStandardError()).trimmed());
        return false;
    }
    run->seconds = double(timer.nsecsElapsed()) / 1e9;
    const QJsonObject json = QJsonDocument::fromJson(cli.readAllStandardOutput()).object();
    for (const QJsonValue& d : json.value(QStringLiteral("drives")).toArray()) {
        run->requests += d.toObject().value(QStringLiteral("requests")).toInt();
        ++run->drives;
    }
    if (run->drives != kDrives) {
        *error =
            QStringLiteral("the backup holds %1 drives, expected %2").arg(run->drives).arg(kDrives);
        return false;
    }
    return true;
}

// The wire time of one DBU200's backup reads: each block's request, reply, turnaround and
// the two 3.5 character gaps.
double wireMsPerDrive(int* requests)
{
    const Profile& dbu = *ProfileRegistry::builtIn().family(QStringLiteral("dbu"));
    QVector<const ParameterMeta*> settings;
    for (const ParameterMeta& p : dbu.parameters) {
        if (p.backup && p.isReadable() && p.isWritable())
            settings << &p;
    }
    const WireTiming wire(kBaud, 'N', 2.0);
    double ms = 0;
    *requests = 0;
    for (const ReadBlockPlan& block : ReadPlanner::plan(dbu, settings)) {
        ms += wire.frameMs(8) + wire.gapMs() + wire.turnaroundMs() +
              wire.frameMs(5 + 2 * block.count) + wire.gapMs();
        ++*requests;
    }
    return ms;
}

} // namespace

QString BusBackupBenchmark::description() const
{
    return QStringLiteral("opentop-cli backup of 32 DBU200s at 115200 bit/s: known drives, "
                          "and --all with its scan");
}

bool BusBackupBenchmark::run(const BenchEnvironment& env, BenchReport& report, QString* error)
{
    SimulatorProcess sim;
    if (!sim.start({QStringLiteral("--devices"), QStringLiteral("dbu200@1-%1").arg(kDrives),
                    QStringLiteral("--wire-timing"), QStringLiteral("--half-duplex"),
                    QStringLiteral("--baud"), QString::number(kBaud)},
                   error))
        return false;
    QTemporaryDir dir;
    CliRun known;
    CliRun all;
    if (!backup(env, sim.pty(), {QStringLiteral("1-%1").arg(kDrives)},
                dir.filePath(QStringLiteral("known.json")), &known, error) ||
        !backup(env, sim.pty(), {QStringLiteral("--all")}, dir.filePath(QStringLiteral("all.json")),
                &all, error))
        return false;
    int planned = 0;
    const double wireMs = wireMsPerDrive(&planned) * kDrives;
    report.note(QStringLiteral("bus-backup: %1 x dbu200 at %2 bit/s, half-duplex line with wire "
                               "timing; the CLI as a process (start-up included)")
                    .arg(kDrives)
                    .arg(kBaud));
    report.add(BenchFigure::atMost(QStringLiteral("bus_backup.known_drives"), known.seconds,
                                   QStringLiteral("s"), 4.0, 2,
                                   QStringLiteral("%1 requests").arg(known.requests)));
    report.add(BenchFigure::plain(QStringLiteral("bus_backup.with_scan"), all.seconds,
                                  QStringLiteral("s"), 2,
                                  QStringLiteral("scan of 1-247 included")));
    report.add(BenchFigure::plain(
        QStringLiteral("bus_backup.wire_need"), wireMs / 1000, QStringLiteral("s"), 2,
        QStringLiteral("%1 block reads x %2 drives on the wire alone").arg(planned).arg(kDrives)));
    report.add(BenchFigure::plain(QStringLiteral("bus_backup.known_drives.wire_fraction"),
                                  wireMs / 1000 / known.seconds, QStringLiteral("x"), 2,
                                  QStringLiteral("of the run is the reads' wire time")));
    return true;
}

} // namespace opentop
