#pragma once

#include <QObject>
#include <QPointer>
#include <functional>
#include <optional>
#include <utility>

namespace opentop {

class DriveStatusPoller;
class MonitorHub;
class StaleLook;

// Follows one drive's alarm state live for its Alarms page: the hub's samples (the page's own
// polling while shown) and the status poller (the alarm banner's source) each report whether
// an alarm is active and which. When what a source reports changes and contradicts what the
// page shows (`contradicts`), or the drive answers again after it did not (a power cycle, a
// cable put back), the follower asks for a read (readNeeded); while a read is under way it
// asks once more after it, if still needed. Each source is followed on its own, so that two
// sources a poll apart never make the page read back and forth.
class AlarmFollower : public QObject
{
    Q_OBJECT
public:
    using Contradicts = std::function<bool(std::optional<bool> active, std::optional<qint64> code)>;

    AlarmFollower(int slave, MonitorHub* hub, DriveStatusPoller* poller, Contradicts contradicts,
                  QObject* parent);

    // The page is shown (its drive polled through the hub) or hidden.
    void setWatching(bool watching, QObject* watcher);
    // A read (or command) of the page is under way / has ended.
    void setReading(bool reading);
    // Whether the state the hub sees is live (null without a hub).
    StaleLook* look() const { return m_look; }
    // Reads asked for by the drive's state, not by a click.
    int readsAsked() const { return m_asked; }

signals:
    void readNeeded();

private:
    using Observation = std::pair<std::optional<bool>, std::optional<qint64>>;
    void observed(int source, std::optional<bool> active, std::optional<qint64> code,
                  bool answeredAgain);
    void ask();

    int m_slave;
    QPointer<MonitorHub> m_hub;
    QPointer<DriveStatusPoller> m_poller;
    Contradicts m_contradicts;
    StaleLook* m_look = nullptr;
    std::optional<Observation> m_observed[2]; // 0: the hub's samples, 1: the status poller
    int m_lastSource = 0;
    bool m_reading = false;
    bool m_askAgain = false;
    bool m_wasAnswering = true;
    int m_asked = 0;
};

} // namespace opentop
