#include "bench/StartupBenchmark.h"

#include "bench/BenchReport.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QProcessEnvironment>
#include <QTemporaryDir>
#include <algorithm>

namespace opentop {

namespace {

constexpr int kRuns = 5;

} // namespace

QString StartupBenchmark::description() const
{
    return QStringLiteral("the GUI from start to a usable window on a simulated bus");
}

bool StartupBenchmark::run(const BenchEnvironment& env, BenchReport& report, QString* error)
{
    QVector<double> wall;
    QVector<double> inside;
    for (int i = 0; i < kRuns; ++i) {
        QTemporaryDir config; // a first start: no remembered settings
        QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
        environment.insert(QStringLiteral("XDG_CONFIG_HOME"), config.path());
        if (!environment.contains(QStringLiteral("QT_QPA_PLATFORM")))
            environment.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
        QProcess gui;
        gui.setProcessEnvironment(environment);
        QElapsedTimer timer;
        timer.start();
        gui.start(env.binDir + QStringLiteral("/opentop"),
                  {QStringLiteral("--sim"), QStringLiteral("dbu200@1,dbu400@150,dcpid@7"),
                   QStringLiteral("--startup-probe")});
        // "ready: 412 ms after main()"
        QString line;
        while (gui.waitForReadyRead(20000) || gui.canReadLine()) {
            if (!gui.canReadLine())
                continue;
            line = QString::fromLocal8Bit(gui.readLine()).trimmed();
            if (line.startsWith(QLatin1String("ready:")))
                break;
        }
        const double ms = double(timer.nsecsElapsed()) / 1e6;
        gui.waitForFinished(10000);
        if (!line.startsWith(QLatin1String("ready:"))) {
            *error = QStringLiteral("opentop did not report a usable window: %1")
                         .arg(QString::fromLocal8Bit(gui.readAllStandardError()).trimmed());
            return false;
        }
        wall << ms;
        inside << line.section(QLatin1Char(' '), 1, 1).toDouble();
    }
    std::sort(wall.begin(), wall.end());
    std::sort(inside.begin(), inside.end());
    report.add(BenchFigure::atMost(
        QStringLiteral("startup.median"), wall.at(kRuns / 2) / 1000, QStringLiteral("s"), 1.0, 3,
        QStringLiteral("process start to the drives painted, %1 runs").arg(kRuns)));
    report.add(BenchFigure::plain(QStringLiteral("startup.slowest"), wall.last() / 1000,
                                  QStringLiteral("s"), 3));
    report.add(BenchFigure::plain(QStringLiteral("startup.after_main"), inside.at(kRuns / 2) / 1000,
                                  QStringLiteral("s"), 3,
                                  QStringLiteral("median from main(); the rest is loading")));
    return true;
}

} // namespace opentop
