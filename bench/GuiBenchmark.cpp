#include "GuiBenchmark.h"

#include "BenchReport.h"
#include "ProcessStats.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QProcessEnvironment>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QThread>
#include <algorithm>

namespace opentop {

namespace {

constexpr double kWarmUpSeconds = 10;

} // namespace

QString GuiBenchmark::description() const
{
    return QStringLiteral("the GUI monitoring 16 drives at 10 Hz and 64 at 2 Hz, overview and "
                          "trends open: CPU and memory");
}

bool GuiBenchmark::run(const BenchEnvironment& env, BenchReport& report, QString* error)
{
    return runCase(env, 16, 100, true, report, error) &&
           runCase(env, 64, 500, false, report, error);
}

bool GuiBenchmark::runCase(const BenchEnvironment& env, int drives, int pollMs, bool goals,
                           BenchReport& report, QString* error)
{
    // The drives are simulated inside the program (--sim): 16 drives at 10 Hz is more than a
    // serial line carries (a sample is several block reads, each with its 3.5-character gaps),
    // and this measures the program's own work. The simulation's CPU is counted with it.
    QTemporaryDir config; // the user's settings are neither read nor changed
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("XDG_CONFIG_HOME"), config.path());
    if (!environment.contains(QStringLiteral("QT_QPA_PLATFORM")))
        environment.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    const double total = kWarmUpSeconds + env.guiSeconds;
    QProcess gui;
    gui.setProcessEnvironment(environment);
    gui.start(env.binDir + QStringLiteral("/opentop"),
              {QStringLiteral("--sim"), QStringLiteral("dbu200@1-%1").arg(drives),
               QStringLiteral("--monitor-all"), QStringLiteral("--poll-ms"),
               QString::number(pollMs), QStringLiteral("--quit-after"),
               QString::number(total + 1)});
    if (!gui.waitForStarted(10000)) {
        *error = QStringLiteral("cannot start opentop: %1").arg(gui.errorString());
        return false;
    }
    const ProcessStats stats(gui.processId());
    QThread::msleep(static_cast<unsigned long>(kWarmUpSeconds * 1000));
    const double cpu0 = stats.cpuSeconds();
    QElapsedTimer timer;
    timer.start();
    double rssMax = 0;
    double rssSum = 0;
    int rssCount = 0;
    while (double(timer.elapsed()) / 1000 < env.guiSeconds) {
        QThread::msleep(1000);
        const double rss = stats.rssMiB();
        if (rss < 0)
            break;
        rssMax = std::max(rssMax, rss);
        rssSum += rss;
        ++rssCount;
    }
    const double cpu1 = stats.cpuSeconds();
    const double wall = double(timer.nsecsElapsed()) / 1e9;
    gui.waitForFinished(30000);
    const QString out = QString::fromLocal8Bit(gui.readAllStandardOutput());
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
