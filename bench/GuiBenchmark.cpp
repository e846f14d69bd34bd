#include "bench/GuiBenchmark.h"

#include "bench/BenchReport.h"
#include "bench/ProcessStats.h"
#include "bench/SimulatorProcess.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QProcessEnvironment>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QThread>
#include <algorithm>

namespace opentop {

namespace {

// The bus scan before monitoring starts (a TCP gateway answers absent numbers at once).
constexpr double kScanAllowanceSeconds = 60;
// Measured at steady state: once the trends' one-minute window is full, each line draws as
// many points as it ever will (measured after 10 s, the figure was half of what a user sees).
constexpr double kWarmUpSeconds = 65;

} // namespace

QString GuiBenchmark::description() const
{
    return QStringLiteral(
        "the GUI monitoring 16 drives at 10 Hz and 64 at 2 Hz, overview and "
        "trends open: CPU and memory at steady state (after a 65 s warm-up that fills the trends' "
        "one-minute window)");
}

bool GuiBenchmark::run(const BenchEnvironment& env, BenchReport& report, QString* error)
{
    return runCase(env, 16, 100, true, report, error) &&
           runCase(env, 64, 500, false, report, error);
}

bool GuiBenchmark::runCase(const BenchEnvironment& env, int drives, int pollMs, bool goals,
                           BenchReport& report, QString* error)
{
    // The drives are simulated by opentop-sim behind a Modbus TCP gateway: 16 drives at 10 Hz
    // is more than a serial line carries (a sample is several block reads, each with its
    // 3.5-character gaps), and the figure is the program's own work, the simulation apart.
    // Every motor turns and changes speed every 5 s, as in a commissioning session: idle
    // drives would draw flat lines, the cheapest case there is.
    SimulatorProcess sim;
    if (!sim.start({QStringLiteral("--devices"), QStringLiteral("dbu200@1-%1").arg(drives),
                    QStringLiteral("--tcp"), QStringLiteral("127.0.0.1:0")},
                   error))
        return false;
    if (sim.tcp().isEmpty()) {
        *error = QStringLiteral("opentop-sim did not say its TCP port");
        return false;
    }
    const auto speeds = [&](int turn) {
        for (int id = 1; id <= drives; ++id)
            sim.command(
                QStringLiteral("vr %1 %2").arg(id).arg(300 + (id * 97 + turn * 700) % 2400));
    };
    const auto motors = [&](bool on) {
        for (int id = 1; id <= drives; ++id)
            sim.command(QStringLiteral("input %1 %2").arg(id).arg(on ? 1 : 0));
    };
    motors(true);
    speeds(0);

    QTemporaryDir config; // the user's settings are neither read nor changed
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("XDG_CONFIG_HOME"), config.path());
    if (!environment.contains(QStringLiteral("QT_QPA_PLATFORM")))
        environment.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    // After the measurement the motors are stopped, and the program must see that before it
    // quits (it would otherwise ask what to do with the running drives).
    const double stopMargin = 10 + drives / 8.0;
    const double total = kScanAllowanceSeconds + kWarmUpSeconds + env.guiSeconds + stopMargin;
    QProcess gui;
    gui.setProcessEnvironment(environment);
    gui.start(env.binDir + QStringLiteral("/opentop"),
              {QStringLiteral("--tcp"), sim.tcp(), QStringLiteral("--monitor-all"),
               QStringLiteral("--poll-ms"), QString::number(pollMs), QStringLiteral("--quit-after"),
               QString::number(int(total) + 1), QStringLiteral("--stats-every"),
               QStringLiteral("1")});
    if (!gui.waitForStarted(10000)) {
        *error = QStringLiteral("cannot start opentop: %1").arg(gui.errorString());
        return false;
    }
    const ProcessStats stats(gui.processId());
    // The bus is scanned first; the warm-up starts once every drive is sampled.
    QString out;
    static const QRegularExpression monitoring(QStringLiteral("^monitor: (\\d+) drives, [1-9]"),
                                               QRegularExpression::MultilineOption);
    QElapsedTimer scan;
    scan.start();
    int seen = 0;
    while (seen < drives && scan.elapsed() < kScanAllowanceSeconds * 1000 &&
           gui.state() == QProcess::Running) {
        gui.waitForReadyRead(500);
        out += QString::fromLocal8Bit(gui.readAllStandardOutput());
        for (auto it = monitoring.globalMatch(out); it.hasNext();)
            seen = std::max(seen, it.next().captured(1).toInt());
    }
    if (seen < drives) {
        *error = QStringLiteral("opentop monitored %1 of %2 drives after %3 s")
                     .arg(seen)
                     .arg(drives)
                     .arg(scan.elapsed() / 1000);
        return false;
    }
    const auto readOutput = [&] { out += QString::fromLocal8Bit(gui.readAllStandardOutput()); };
    QElapsedTimer warm;
    warm.start();
    int turn = 0;
    while (double(warm.elapsed()) / 1000 < kWarmUpSeconds) {
        gui.waitForReadyRead(1000);
        readOutput();
        if (warm.elapsed() / 5000 > turn)
            speeds(++turn % 2);
    }
    const double cpu0 = stats.cpuSeconds();
    QElapsedTimer timer;
    timer.start();
    double rssMax = 0;
    double rssSum = 0;
    int rssCount = 0;
    for (int second = 1; double(timer.elapsed()) / 1000 < env.guiSeconds; ++second) {
        gui.waitForReadyRead(1000);
        readOutput();
        const double rss = stats.rssMiB();
        if (rss < 0)
            break;
        rssMax = std::max(rssMax, rss);
        rssSum += rss;
        ++rssCount;
        if (second % 5 == 0)
            speeds(++turn % 2);
    }
    const double cpu1 = stats.cpuSeconds();
    const double wall = double(timer.nsecsElapsed()) / 1e9;
    motors(false);
    gui.waitForFinished(int((total + 30) * 1000));
    readOutput();
    if (cpu0 < 0 || cpu1 < 0 || rssCount == 0) {
        *error = QStringLiteral("opentop ended early: %1")
                     .arg(QString::fromLocal8Bit(gui.readAllStandardError()).trimmed());
        return false;
    }
    // "drive 3: 612 samples, 0 errors, 9.98 samples/s"
    static const QRegularExpression line(
        QStringLiteral("^drive \\d+: \\d+ samples, (\\d+) errors, ([0-9.]+) samples/s$"),
        QRegularExpression::MultilineOption);
    double slowest = -1;
    int errors = 0;
    int watched = 0;
    for (auto it = line.globalMatch(out); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        errors += m.captured(1).toInt();
        const double rate = m.captured(2).toDouble();
        slowest = slowest < 0 ? rate : std::min(slowest, rate);
        ++watched;
    }
    if (watched != drives) {
        *error =
            QStringLiteral("opentop monitored %1 drives, expected %2").arg(watched).arg(drives);
        return false;
    }
    const QString key = QStringLiteral("gui.%1x%2Hz").arg(drives).arg(1000 / pollMs);
    const double cpuPercent = (cpu1 - cpu0) / wall * 100;
    if (goals) {
        report.add(BenchFigure::atMost(key + QStringLiteral(".cpu"), cpuPercent,
                                       QStringLiteral("% of a core"), 10, 1));
        report.add(BenchFigure::atMost(key + QStringLiteral(".rss_max"), rssMax,
                                       QStringLiteral("MiB"), 120, 0));
    } else {
        report.add(BenchFigure::plain(key + QStringLiteral(".cpu"), cpuPercent,
                                      QStringLiteral("% of a core"), 1));
        report.add(
            BenchFigure::plain(key + QStringLiteral(".rss_max"), rssMax, QStringLiteral("MiB"), 0));
    }
    report.add(BenchFigure::plain(key + QStringLiteral(".rss_mean"), rssSum / rssCount,
                                  QStringLiteral("MiB"), 0));
    // The load is only what it claims when every drive is sampled at the rate asked for.
    report.add(BenchFigure::atLeast(key + QStringLiteral(".slowest_drive"), slowest,
                                    QStringLiteral("samples/s"), 0.95 * 1000 / pollMs, 2,
                                    QStringLiteral("%1 errors over the run").arg(errors)));
    return true;
}

} // namespace opentop
