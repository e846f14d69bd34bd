#pragma once

#include "model/monitor/DeviceMonitor.h"
#include "model/monitor/TrendHistory.h"
#include "model/session/Freshness.h"

#include <QHash>
#include <QObject>
#include <QPointer>
#include <QSet>
#include <memory>
#include <optional>
#include <unordered_map>

namespace opentop {

class BusDrives;

// Live monitoring of the drives of a bus, shared by every view that shows it (a drive's
// monitor page, the trend charts, the bus overview): one DeviceMonitor per drive, polling
// while at least one view watches it, all at one selectable interval and at Poll priority, so
// that user commands always go first and the drives share the bus in turn; a drive whose pages
// are open is recorded (polled once a second) while none of its views is in sight, so that its
// trend has no gap when the user comes back. Keeps each drive's
// latest sample and a bounded history for trends, also after the last view has closed: an
// hour at 10 Hz per series for up to kFullHistoryDrives drives, and for more drives a share of
// the same budget each (247 drives: 2331 points per series, over 6 hours at one sample every
// 10 s), so that the histories' memory does not grow with the number of drives.
class MonitorHub : public QObject
{
    Q_OBJECT
public:
    struct Statistics
    {
        qint64 samples = 0;
        qint64 errors = 0;
        int errorsInRow = 0; // polls in a row that failed since the last sample
        qint64 firstMs = 0;  // time of the first sample since polling (re)started
        qint64 lastMs = 0;
        // Times of the latest samples (at most kRateWindow, all of the current polling run).
        QVector<qint64> recentMs;
        static constexpr int kRateWindow = 16;
        // Samples per second now: over the latest samples of the current polling run, so
        // that a pause (hidden page, paused polling) does not dilute it.
        double rate() const;
        void add(qint64 ms);
    };

    static constexpr int kFullHistoryPoints = 36000; // per series: one hour at 10 Hz
    static constexpr int kFullHistoryDrives = 16;
    static constexpr int kMinHistoryPoints = 600;
    // Points per series each drive's history keeps while the hub knows `drives` drives.
    static int historyCapacity(int drives);

    explicit MonitorHub(BusDrives* drives, QObject* parent = nullptr);
    ~MonitorHub() override;

    BusDrives* drives() const { return m_drives; }
    // Starts polling `slave` while `watcher` exists and has not called unwatch().
    void watch(int slave, QObject* watcher);
    void unwatch(int slave, QObject* watcher);
    bool isWatched(int slave) const;
    QVector<int> watched() const;
    // Keeps `slave` polled at kRecordIntervalMs (or the interval, when that is longer) while
    // `recorder` exists and no view watches it, so that its trend goes on without a gap while
    // its Monitor page is behind another page; stopRecording() or the recorder's end ends it.
    void record(int slave, QObject* recorder);
    void stopRecording(int slave, QObject* recorder);
    // Polled now only to keep its trend: no view watches it.
    bool isRecordingOnly(int slave) const;
    static constexpr int kRecordIntervalMs = 1000;

    // Milliseconds from the start of one poll of a drive to the start of its next.
    void setInterval(int ms);
    int interval() const { return m_intervalMs; }
    // Stops and resumes every drive's polling (the views keep what they have).
    void setPaused(bool paused);
    bool isPaused() const { return m_paused; }
    // Polling waits for a bus scan, which holds the bus (ModbusClient::holdPolling); the
    // values shown age meanwhile.
    bool isHeld() const;

    std::optional<MonitorSample> latest(int slave) const;
    const TrendHistory* history(int slave) const;
    Statistics statistics(int slave) const;
    QString lastError(int slave) const;
    // Whether the latest value of `slave` may be shown as live (monitor/Freshness): read
    // within a few intervals, the link up and the drive answering its last polls.
    Freshness::State freshness(int slave, const QDateTime& now) const;
    // When `slave` last answered a poll (invalid: never).
    QDateTime lastAnswer(int slave) const;
    // Re-reads the speed display settings of `slave` (after they were written).
    void refreshDisplay(int slave);
    DeviceMonitor* monitor(int slave) const;

signals:
    void sample(int slave, const opentop::MonitorSample& sample);
    void error(int slave, const QString& text);
    void watchedChanged();
    void intervalChanged(int ms);
    void pausedChanged(bool paused);
    void heldChanged(bool held);
    // The link went down or up: every drive's values changed freshness at once.
    void linkChanged(bool up);

private:
    struct Drive
    {
        std::unique_ptr<DeviceMonitor> monitor;
        QSet<QObject*> watchers;
        QSet<QObject*> recorders; // keep the trend going at kRecordIntervalMs
        std::optional<MonitorSample> latest;
        TrendHistory history;
        Statistics stats;
        QString lastError;
        bool prepared = false;
    };

    Drive* driveFor(int slave);
    void startOrStop(int slave);
    void forget(int slave);
    void identified(int slave);
    void release(QObject* watcher);
    void follow(QObject* watcher); // release() when it is destroyed
    int intervalOf(const Drive& drive) const;
    void shareHistory();

    BusDrives* m_drives;
    std::unordered_map<int, std::unique_ptr<Drive>> m_list;
    QSet<QObject*> m_watchers; // connected to their destroyed() signal
    int m_intervalMs = 200;
    bool m_paused = false;
};

} // namespace opentop
