#include "model/monitor/MonitorHub.h"

#include "model/ModelLog.h"
#include "model/bus/BusDrives.h"
#include "model/session/DeviceSession.h"
#include "transport/ModbusClient.h"

#include <algorithm>

namespace opentop {

double MonitorHub::Statistics::rate() const
{
    const qint64 n = recentMs.size();
    return n > 1 && recentMs.last() > recentMs.first()
               ? (n - 1) * 1000.0 / double(recentMs.last() - recentMs.first())
               : 0.0;
}

void MonitorHub::Statistics::add(qint64 ms)
{
    if (samples++ == 0 || recentMs.isEmpty())
        firstMs = ms;
    lastMs = ms;
    errorsInRow = 0;
    recentMs << ms;
    if (recentMs.size() > kRateWindow)
        recentMs.removeFirst();
}

MonitorHub::MonitorHub(BusDrives* drives, QObject* parent)
    : QObject(parent)
    , m_drives(drives)
{
    connect(drives, &BusDrives::driveRemoved, this, &MonitorHub::forget);
    connect(drives, &BusDrives::driveAdded, this, &MonitorHub::identified);
    connect(drives, &BusDrives::driveChanged, this, &MonitorHub::identified);
    connect(drives, &BusDrives::linkChanged, this, &MonitorHub::linkChanged);
    if (drives->client())
        connect(drives->client(), &ModbusClient::pollingHeldChanged, this,
                &MonitorHub::heldChanged);
}

bool MonitorHub::isHeld() const
{
    return m_drives->client() && m_drives->client()->isPollingHeld();
}

// A drive identified again may have a new session: the old monitor would poll a dead one.
void MonitorHub::identified(int slave)
{
    const auto it = m_list.find(slave);
    if (it == m_list.end())
        return;
    if (it->second->monitor && it->second->monitor->session() != m_drives->session(slave)) {
        it->second->monitor.reset();
        it->second->prepared = false;
    }
    // Watched before it was identified: it can be polled now.
    startOrStop(slave);
}

MonitorHub::~MonitorHub() = default;

int MonitorHub::historyCapacity(int drives)
{
    const qint64 budget = qint64(kFullHistoryPoints) * kFullHistoryDrives;
    return int(
        std::clamp<qint64>(budget / std::max(1, drives), kMinHistoryPoints, kFullHistoryPoints));
}

MonitorHub::Drive* MonitorHub::driveFor(int slave)
{
    auto& d = m_list[slave];
    if (!d) {
        d = std::make_unique<Drive>();
        shareHistory();
    }
    return d.get();
}

void MonitorHub::shareHistory()
{
    const int capacity = historyCapacity(int(m_list.size()));
    for (auto& [slave, d] : m_list) {
        if (d && d->history.capacity() != capacity)
            d->history.setCapacity(capacity);
    }
}

void MonitorHub::follow(QObject* watcher)
{
    // A view that goes away stops watching by itself.
    if (!m_watchers.contains(watcher)) {
        m_watchers.insert(watcher);
        connect(watcher, &QObject::destroyed, this, [this, watcher] { release(watcher); });
    }
}

void MonitorHub::watch(int slave, QObject* watcher)
{
    Drive* d = driveFor(slave);
    if (d->watchers.contains(watcher))
        return;
    d->watchers.insert(watcher);
    follow(watcher);
    startOrStop(slave);
    emit watchedChanged();
}

void MonitorHub::record(int slave, QObject* recorder)
{
    Drive* d = driveFor(slave);
    if (d->recorders.contains(recorder))
        return;
    d->recorders.insert(recorder);
    follow(recorder);
    startOrStop(slave);
}

void MonitorHub::stopRecording(int slave, QObject* recorder)
{
    const auto it = m_list.find(slave);
    if (it == m_list.end() || !it->second->recorders.remove(recorder))
        return;
    startOrStop(slave);
}

bool MonitorHub::isRecordingOnly(int slave) const
{
    const auto it = m_list.find(slave);
    return it != m_list.end() && it->second->watchers.isEmpty() &&
           !it->second->recorders.isEmpty() && it->second->monitor &&
           it->second->monitor->isActive();
}

int MonitorHub::intervalOf(const Drive& drive) const
{
    return drive.watchers.isEmpty() ? std::max(m_intervalMs, kRecordIntervalMs) : m_intervalMs;
}

void MonitorHub::unwatch(int slave, QObject* watcher)
{
    const auto it = m_list.find(slave);
    if (it == m_list.end() || !it->second->watchers.remove(watcher))
        return;
    startOrStop(slave);
    emit watchedChanged();
}

void MonitorHub::release(QObject* watcher)
{
    m_watchers.remove(watcher);
    QVector<int> slaves, recorded;
    for (const auto& [slave, d] : m_list) {
        if (d->watchers.contains(watcher))
            slaves << slave;
        if (d->recorders.contains(watcher))
            recorded << slave;
    }
    for (int slave : slaves)
        unwatch(slave, watcher);
    for (int slave : recorded)
        stopRecording(slave, watcher);
}

bool MonitorHub::isWatched(int slave) const
{
    const auto it = m_list.find(slave);
    return it != m_list.end() && !it->second->watchers.isEmpty();
}

QVector<int> MonitorHub::watched() const
{
    QVector<int> slaves;
    for (const auto& [slave, d] : m_list) {
        if (!d->watchers.isEmpty())
            slaves << slave;
    }
    std::sort(slaves.begin(), slaves.end());
    return slaves;
}

void MonitorHub::startOrStop(int slave)
{
    Drive* d = driveFor(slave);
    const bool wanted = (!d->watchers.isEmpty() || !d->recorders.isEmpty()) && !m_paused;
    if (!wanted) {
        if (d->monitor)
            d->monitor->stop();
        return;
    }
    DeviceSession* session = m_drives->session(slave);
    if (!session)
        return; // not identified (yet): driveChanged starts it
    if (!d->monitor) {
        d->monitor = std::make_unique<DeviceMonitor>(session);
        connect(d->monitor.get(), &DeviceMonitor::sample, this,
                [this, slave](const QDateTime&, const MonitorSample& s) {
                    Drive* drive = driveFor(slave);
                    drive->stats.add(s.timestamp.toMSecsSinceEpoch());
                    drive->latest = s;
                    drive->lastError.clear();
                    drive->history.append(s);
                    emit sample(slave, s);
                });
        connect(d->monitor.get(), &DeviceMonitor::error, this, [this, slave](const QString& text) {
            Drive* drive = driveFor(slave);
            ++drive->stats.errors;
            ++drive->stats.errorsInRow;
            drive->lastError = text;
            emit error(slave, text);
        });
    }
    const int interval = intervalOf(*d);
    if (d->monitor->isActive()) {
        if (d->monitor->interval() != interval) {
            // From recording to watching or back: the rate shown is that of the new run.
            d->monitor->setInterval(interval);
            d->stats.recentMs.clear();
        }
        return;
    }
    d->monitor->setInterval(interval);
    d->stats.recentMs.clear(); // the rate is that of this polling run
    if (d->prepared) {
        d->monitor->start();
        return;
    }
    // The speed display settings first, so that samples carry the drive's display values.
    d->monitor->prepare([this, slave](const QString& problem) {
        if (m_list.find(slave) == m_list.end())
            return; // forgotten meanwhile
        Drive* drive = driveFor(slave);
        drive->prepared = true;
        if (!problem.isEmpty())
            qCWarning(lcModel) << "speed display of" << slave << ":" << problem;
        if (drive->monitor && (!drive->watchers.isEmpty() || !drive->recorders.isEmpty()) &&
            !m_paused)
            drive->monitor->start();
    });
}

void MonitorHub::setInterval(int ms)
{
    ms = std::max(20, ms);
    if (ms == m_intervalMs)
        return;
    m_intervalMs = ms;
    for (auto& [slave, d] : m_list) {
        if (d->monitor)
            d->monitor->setInterval(intervalOf(*d));
    }
    emit intervalChanged(ms);
}

void MonitorHub::setPaused(bool paused)
{
    if (paused == m_paused)
        return;
    m_paused = paused;
    QVector<int> slaves;
    for (const auto& [slave, d] : m_list)
        slaves << slave;
    for (int slave : slaves)
        startOrStop(slave);
    emit pausedChanged(paused);
}

std::optional<MonitorSample> MonitorHub::latest(int slave) const
{
    const auto it = m_list.find(slave);
    return it == m_list.end() ? std::nullopt : it->second->latest;
}

const TrendHistory* MonitorHub::history(int slave) const
{
    const auto it = m_list.find(slave);
    return it == m_list.end() ? nullptr : &it->second->history;
}

MonitorHub::Statistics MonitorHub::statistics(int slave) const
{
    const auto it = m_list.find(slave);
    return it == m_list.end() ? Statistics() : it->second->stats;
}

QString MonitorHub::lastError(int slave) const
{
    const auto it = m_list.find(slave);
    return it == m_list.end() ? QString() : it->second->lastError;
}

void MonitorHub::refreshDisplay(int slave)
{
    const auto it = m_list.find(slave);
    if (it == m_list.end() || !it->second->monitor)
        return;
    it->second->monitor->prepare([](const QString& problem) {
        if (!problem.isEmpty())
            qCWarning(lcModel) << "speed display:" << problem;
    });
}

QDateTime MonitorHub::lastAnswer(int slave) const
{
    const auto it = m_list.find(slave);
    return it == m_list.end() || !it->second->latest ? QDateTime() : it->second->latest->timestamp;
}

Freshness::State MonitorHub::freshness(int slave, const QDateTime& now) const
{
    const auto it = m_list.find(slave);
    if (it == m_list.end() || !it->second->latest)
        return Freshness::State::None;
    // A drive that failed its last polls does not answer, however recent its last value; a
    // value not being polled (paused, or waiting for a scan) is not live either.
    const bool answers = it->second->stats.errorsInRow < 2;
    return Freshness::of(it->second->latest->timestamp, now, m_intervalMs,
                         m_drives->linkUp() && answers && !m_paused && !isHeld());
}

DeviceMonitor* MonitorHub::monitor(int slave) const
{
    const auto it = m_list.find(slave);
    return it == m_list.end() ? nullptr : it->second->monitor.get();
}

void MonitorHub::forget(int slave)
{
    m_list.erase(slave);
    shareHistory();
    emit watchedChanged();
}

} // namespace opentop
