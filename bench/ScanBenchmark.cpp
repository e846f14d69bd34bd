#include "bench/ScanBenchmark.h"

#include "bench/BenchReport.h"
#include "bench/PlainModbusLoop.h"
#include "bench/SimulatorProcess.h"
#include "model/bus/BusScanner.h"
#include "model/profile/ProfileRegistry.h"
#include "transport/ModbusClient.h"
#include "transport/RtuBackend.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QProcess>
#include <QStandardPaths>
#include <QTimer>

namespace opentop {

namespace {

// A bus as found in the field, and a drive that answers as late as the DBU manual allows:
// T3 (initial value 10 ms) + C1 (command processing, < 4 ms) after the 3.5 character gap.
const QString kBus = QStringLiteral("dbu200@1,dcpid@7,dbu200@60{turnaround=14},dbu400@150");
const QVector<int> kExpected = {1, 7, 60, 150};
constexpr int kLateDrive = 60;

QString list(const QVector<int>& ids)
{
    QStringList parts;
    for (int id : ids)
        parts << QString::number(id);
    return parts.isEmpty() ? QStringLiteral("none") : parts.join(QLatin1Char(','));
}

// mbpoll asks `slaves` machine numbers nobody has, with its default timeout (1 s): seconds
// per address, process start included; < 0 when mbpoll is not installed.
double mbpollPerAbsentAddress(const QString& port, int baud, const QVector<int>& slaves)
{
    const QString mbpoll = QStandardPaths::findExecutable(QStringLiteral("mbpoll"));
    if (mbpoll.isEmpty())
        return -1;
    QElapsedTimer timer;
    timer.start();
    for (int slave : slaves) {
        QProcess p;
        p.start(mbpoll, {QStringLiteral("-m"), QStringLiteral("rtu"), QStringLiteral("-a"),
                         QString::number(slave), QStringLiteral("-b"), QString::number(baud),
                         QStringLiteral("-P"), QStringLiteral("none"), QStringLiteral("-t"),
                         QStringLiteral("4"), QStringLiteral("-0"), QStringLiteral("-r"),
                         QStringLiteral("0"), QStringLiteral("-1"), port});
        p.waitForFinished(10000);
    }
    return double(timer.nsecsElapsed()) / 1e9 / slaves.size();
}

} // namespace

QString ScanBenchmark::description() const
{
    return QStringLiteral("scan 1-247 at 19200 and 115200 bit/s, turnaround 2 and 10 ms, one "
                          "drive answering late; peers: plain libmodbus, mbpoll");
}

ScanBenchmark::Scan ScanBenchmark::scan(ModbusClient* client, int from, int to)
{
    Scan result;
    BusScanner scanner(client, ProfileRegistry::builtIn());
    scanner.setRange(from, to);
    result.waitMs = scanner.waitMs();
    QEventLoop loop;
    QObject::connect(&scanner, &BusScanner::finished, &loop, &QEventLoop::quit);
    QTimer::singleShot(120000, &loop, &QEventLoop::quit);
    scanner.start();
    if (scanner.isRunning())
        loop.exec();
    if (scanner.isRunning() || !scanner.error().isEmpty() || scanner.wasCancelled()) {
        result.error =
            scanner.error().isEmpty() ? QStringLiteral("the scan did not finish") : scanner.error();
        return result;
    }
    for (const DeviceInfo& info : scanner.devices()) {
        if (info.state == DeviceInfo::State::Present)
            result.present << info.slave;
    }
    result.seconds = scanner.elapsedMs() / 1000.0;
    result.requests = scanner.requestsSent();
    result.rescued = scanner.lateAnswers();
    return result;
}

bool ScanBenchmark::run(const BenchEnvironment&, BenchReport& report, QString* error)
{
    report.note(QStringLiteral("scan: bus %1 (60 answers 14 ms after the gap), half-duplex "
                               "line with wire timing")
                    .arg(kBus));
    return runCase(19200, 2, true, report, error) && runCase(19200, 10, false, report, error) &&
           runCase(115200, 2, true, report, error) && runCase(115200, 10, false, report, error);
}

bool ScanBenchmark::runCase(int baud, double turnaroundMs, bool peers, BenchReport& report,
                            QString* error)
{
    SimulatorProcess sim;
    if (!sim.start({QStringLiteral("--devices"), kBus, QStringLiteral("--wire-timing"),
                    QStringLiteral("--half-duplex"), QStringLiteral("--baud"),
                    QString::number(baud), QStringLiteral("--turnaround"),
                    QString::number(turnaroundMs)},
                   error))
        return false;
    const QString key = QStringLiteral("scan.%1.t%2").arg(baud).arg(turnaroundMs);
    Scan full;
    Scan absent;
    {
        const ConnectionSettings settings = sim.lineSettings(baud);
        ModbusClient client(std::make_unique<RtuBackend>(settings), settings);
        *error = client.openBlocking();
        if (!error->isEmpty())
            return false;
        full = scan(&client, 1, 247);
        absent = scan(&client, 200, 247); // nobody has 200-247
    }
    if (!full.error.isEmpty() || !absent.error.isEmpty()) {
        *error = full.error.isEmpty() ? absent.error : full.error;
        return false;
    }
    if (full.present != kExpected) {
        *error = QStringLiteral("%1: found %2, expected %3")
                     .arg(key, list(full.present), list(kExpected));
        return false;
    }
    const double perAbsentMs = absent.seconds * 1000 / 48;
    if (baud == 19200 && turnaroundMs == 2)
        report.add(BenchFigure::atMost(
            key + QStringLiteral(".time"), full.seconds, QStringLiteral("s"), 5.0, 2,
            QStringLiteral("all 4 drives found, %1 asked again").arg(full.rescued)));
    else
        report.add(BenchFigure::plain(
            key + QStringLiteral(".time"), full.seconds, QStringLiteral("s"), 2,
            QStringLiteral("all 4 drives found, %1 asked again").arg(full.rescued)));
    report.add(BenchFigure::plain(
        key + QStringLiteral(".per_absent_address"), perAbsentMs, QStringLiteral("ms"), 1,
        QStringLiteral("wait %1 ms for the first byte").arg(full.waitMs)));
    if (!peers)
        return true;

    // Peers on the same line: a plain loop with the same wait finds what answers in time.
    PlainModbusLoop plain(sim.pty(), baud);
    if (!plain.open(error))
        return false;
    const IdentifyRule& identify =
        ProfileRegistry::builtIn().family(QStringLiteral("dbu"))->identify;
    const PlainModbusLoop::ScanResult loop =
        plain.scan(1, 247, identify.address, identify.count, full.waitMs);
    report.add(BenchFigure::plain(
        key + QStringLiteral(".plain_libmodbus"), loop.seconds, QStringLiteral("s"), 2,
        QStringLiteral("same wait, no rescue: found %1%2")
            .arg(list(loop.found), loop.found.contains(kLateDrive)
                                       ? QString()
                                       : QStringLiteral(" (not the late drive)"))));
    report.add(BenchFigure::plain(key + QStringLiteral(".ratio_to_plain"),
                                  full.seconds / loop.seconds, QStringLiteral("x"), 2));
    if (baud == 19200) {
        const double mbpoll = mbpollPerAbsentAddress(sim.pty(), baud, {201, 202, 203});
        if (mbpoll > 0)
            report.add(BenchFigure::plain(
                key + QStringLiteral(".mbpoll_default"), mbpoll * 247, QStringLiteral("s"), 0,
                QStringLiteral("mbpoll's 1 s timeout: %1 s per absent address x 247")
                    .arg(mbpoll, 0, 'f', 2)));
    }
    return true;
}

} // namespace opentop
