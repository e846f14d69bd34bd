#include "app/gui/MonitorOptions.h"

#include "model/bus/BusDrives.h"
#include "model/monitor/MonitorHub.h"
#include "transport/TrafficLog.h"
#include "ui/bus/BusPanel.h"
#include "ui/main/MainWindow.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QDateTime>
#include <QTimer>
#include <cstdio>

namespace opentop {

namespace {

const QString kMonitorAll = QStringLiteral("monitor-all");
const QString kPollMs = QStringLiteral("poll-ms");
const QString kQuitAfter = QStringLiteral("quit-after");
const QString kStatsEvery = QStringLiteral("stats-every");

// One line of running totals (tests/soak reads it): the samples and errors since monitoring
// began, how many watched drives' values are not live now (monitor/Freshness), the points
// their trend histories hold, and how full the traffic log is (it grows to its capacity, then
// stays there: the soak judges memory once it is full).
void printRunningTotals(const MonitorHub& hub, const TrafficLog* log)
{
    const QDateTime now = QDateTime::currentDateTime();
    qint64 samples = 0;
    qint64 errors = 0;
    int notLive = 0;
    qint64 points = 0;
    const QVector<int> slaves = hub.watched();
    for (int slave : slaves) {
        if (const TrendHistory* history = hub.history(slave))
            points += history->pointCount();
        const MonitorHub::Statistics st = hub.statistics(slave);
        samples += st.samples;
        errors += st.errors;
        if (hub.freshness(slave, now) != Freshness::State::Live)
            ++notLive;
    }
    std::printf("monitor: %d drives, %lld samples, %lld errors, %d stale, %lld trend points, "
                "%d of %d traffic frames\n",
                int(slaves.size()), static_cast<long long>(samples), static_cast<long long>(errors),
                notLive, static_cast<long long>(points), log ? log->size() : 0,
                log ? log->capacity() : 0);
    std::fflush(stdout);
}

void printStatistics(const MonitorHub& hub)
{
    double total = 0;
    qint64 samples = 0;
    qint64 errors = 0;
    for (int slave : hub.watched()) {
        const MonitorHub::Statistics st = hub.statistics(slave);
        std::printf("drive %d: %lld samples, %lld errors, %.2f samples/s\n", slave,
                    static_cast<long long>(st.samples), static_cast<long long>(st.errors),
                    st.rate());
        total += st.rate();
        samples += st.samples;
        errors += st.errors;
    }
    std::printf("monitored %d drives: %lld samples, %lld errors, %.1f samples/s in all\n",
                int(hub.watched().size()), static_cast<long long>(samples),
                static_cast<long long>(errors), total);
    std::fflush(stdout);
}

} // namespace

void MonitorOptions::addTo(QCommandLineParser& parser)
{
    parser.addOptions(
        {{kMonitorAll,
          QApplication::translate("main", "Open the bus overview and the trends of every drive.")},
         {kPollMs, QApplication::translate("main", "Monitoring poll interval in milliseconds."),
          QStringLiteral("ms")},
         {kQuitAfter,
          QApplication::translate("main", "Quit after this many seconds and print the monitoring "
                                          "statistics (for measurements)."),
          QStringLiteral("seconds")},
         {kStatsEvery,
          QApplication::translate("main", "Print the monitoring totals every this many seconds "
                                          "(for measurements)."),
          QStringLiteral("seconds")}});
}

bool MonitorOptions::apply(const QCommandLineParser& parser, MainWindow* window, QString* error)
{
    bool ok = true;
    const int interval = parser.isSet(kPollMs) ? parser.value(kPollMs).toInt(&ok) : 0;
    if (!ok || interval < 0) {
        *error = QApplication::translate("main", "--poll-ms needs a number of milliseconds");
        return false;
    }
    const double seconds = parser.isSet(kQuitAfter) ? parser.value(kQuitAfter).toDouble(&ok) : 0;
    if (!ok || seconds < 0) {
        *error = QApplication::translate("main", "--quit-after needs a number of seconds");
        return false;
    }
    const double every = parser.isSet(kStatsEvery) ? parser.value(kStatsEvery).toDouble(&ok) : 0;
    if (!ok || every < 0) {
        *error = QApplication::translate("main", "--stats-every needs a number of seconds");
        return false;
    }
    const bool all = parser.isSet(kMonitorAll);
    QObject::connect(window, &MainWindow::connectionChanged, window,
                     [window, interval, all](bool connected) {
                         if (!connected || !window->monitorHub())
                             return;
                         if (interval > 0)
                             window->monitorHub()->setInterval(interval);
                         if (!all)
                             return;
                         // A simulated bus's drives are identified at once; on a real line
                         // they are found by a scan first.
                         QTimer::singleShot(1000, window, [window] {
                             if (!window->drives()->slaves().isEmpty()) {
                                 window->monitorAll();
                                 return;
                             }
                             QObject::connect(window->busPanel(), &BusPanel::scanFinished, window,
                                              [window] { window->monitorAll(); });
                             window->busPanel()->startScan(1, 247);
                         });
                     });
    if (every > 0) {
        auto* timer = new QTimer(window);
        QObject::connect(timer, &QTimer::timeout, window, [window] {
            if (window->monitorHub())
                printRunningTotals(*window->monitorHub(), window->trafficLog());
        });
        timer->start(int(every * 1000));
    }
    if (seconds > 0) {
        QTimer::singleShot(int(seconds * 1000), window, [window] {
            if (window->monitorHub())
                printStatistics(*window->monitorHub());
            QApplication::quit();
        });
    }
    return true;
}

} // namespace opentop
