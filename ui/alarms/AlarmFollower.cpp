#include "ui/alarms/AlarmFollower.h"

#include "model/bus/DriveStatusPoller.h"
#include "model/monitor/MonitorHub.h"
#include "ui/widgets/StaleLook.h"

namespace opentop {

AlarmFollower::AlarmFollower(int slave, MonitorHub* hub, DriveStatusPoller* poller,
                             Contradicts contradicts, QObject* parent)
    : QObject(parent)
    , m_slave(slave)
    , m_hub(hub)
    , m_poller(poller)
    , m_contradicts(std::move(contradicts))
{
    if (hub) {
        connect(hub, &MonitorHub::sample, this, [this](int s, const MonitorSample& sample) {
            if (s == m_slave)
                observed(0, sample.alarmActive, sample.activeAlarmCode, false);
        });
        // A deleted page lingers (deleteLater) and may outlive the hub (a reconnection).
        const QPointer<MonitorHub> alive(hub);
        m_look = new StaleLook(
            [alive, slave](const QDateTime& now) {
                return alive ? alive->freshness(slave, now) : Freshness::State::None;
            },
            [alive, slave] { return alive ? alive->lastAnswer(slave) : QDateTime(); }, this);
        connect(hub, &MonitorHub::linkChanged, m_look, &StaleLook::update);
    }
    if (poller) {
        connect(poller, &DriveStatusPoller::statusChanged, this, [this](int s) {
            if (s != m_slave || !m_poller)
                return;
            const DriveStatus st = m_poller->status(m_slave);
            const bool answering = st.polled && st.consecutiveFailures == 0;
            const bool again = answering && !m_wasAnswering;
            m_wasAnswering = answering || !st.polled;
            if (answering)
                observed(1, st.alarmActive,
                         st.alarmActive.value_or(false) ? st.alarmCode : std::nullopt, again);
        });
    }
}

void AlarmFollower::setWatching(bool watching, QObject* watcher)
{
    if (!m_hub)
        return;
    if (watching)
        m_hub->watch(m_slave, watcher);
    else
        m_hub->unwatch(m_slave, watcher);
}

void AlarmFollower::setReading(bool reading)
{
    m_reading = reading;
    if (reading || !m_askAgain)
        return;
    // The drive's state changed while the page read: once more if it still differs.
    m_askAgain = false;
    const std::optional<Observation>& seen = m_observed[m_lastSource];
    if (seen && m_contradicts(seen->first, seen->second))
        ask();
}

void AlarmFollower::observed(int source, std::optional<bool> active, std::optional<qint64> code,
                             bool answeredAgain)
{
    const Observation now(active, code);
    const bool changed = !m_observed[source] || *m_observed[source] != now;
    m_observed[source] = now;
    m_lastSource = source;
    if (!answeredAgain && (!changed || !m_contradicts(active, code)))
        return;
    if (m_reading) {
        m_askAgain = true;
        return;
    }
    ask();
}

void AlarmFollower::ask()
{
    ++m_asked;
    emit readNeeded();
}

} // namespace opentop
