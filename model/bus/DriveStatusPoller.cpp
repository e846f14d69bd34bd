#include "model/bus/DriveStatusPoller.h"

#include "model/bus/BusDrives.h"
#include "model/profile/CodeTable.h"
#include "model/profile/RoleEvaluator.h"
#include "model/profile/ValueCodec.h"
#include "model/session/DeviceSession.h"
#include "transport/ModbusClient.h"

#include <QDateTime>
#include <algorithm>
#include <memory>

namespace opentop {

namespace {

const QString kRunning = QStringLiteral("running");
const QString kAlarmActive = QStringLiteral("alarmActive");
const QString kReverse = QStringLiteral("reverse");
const QString kPriority = QStringLiteral("motionPriority");
const QString kAlarmTable = QStringLiteral("alarm");

// The DBU's alarm codes with their own LED colour, for profiles whose table does not say.
constexpr qint64 kExternalInterrupt = 0x0F;
constexpr qint64 kMemoryError = 0x0D;

} // namespace

DriveStatusPoller::DriveStatusPoller(BusDrives* drives, QObject* parent)
    : QObject(parent)
    , m_drives(drives)
{
    m_timer.setSingleShot(true);
    connect(&m_timer, &QTimer::timeout, this, &DriveStatusPoller::startCycle);
    connect(drives, &BusDrives::driveRemoved, this, [this](int slave) {
        m_status.remove(slave);
        m_queue.removeAll(slave);
        skipIfGone(slave);
    });
    // Every light follows the link at once, not at the next poll; so it does when a scan
    // holds the bus (polling waits) and releases it.
    const auto everyLight = [this] {
        for (int slave : m_status.keys())
            emit statusChanged(slave);
    };
    connect(drives, &BusDrives::linkChanged, this, everyLight);
    if (drives->client())
        connect(drives->client(), &ModbusClient::pollingHeldChanged, this, everyLight);
    // A drive identified again as another family (or as absent) starts afresh.
    connect(drives, &BusDrives::driveChanged, this, [this](int slave) {
        if (!m_drives->session(slave) && m_status.remove(slave))
            emit statusChanged(slave);
        skipIfGone(slave);
    });
}

DriveStatusPoller::~DriveStatusPoller()
{
    stop();
}

QStringList DriveStatusPoller::parametersFor(int slave) const
{
    DeviceSession* session = m_drives->session(slave);
    if (!session)
        return {};
    QStringList names;
    for (const QString& role : {kRunning, kAlarmActive, kReverse, kPriority}) {
        const ParameterMeta* meta = RoleEvaluator::parameter(session->profile(), role);
        if (meta && meta->isReadable() && !names.contains(meta->name))
            names << meta->name;
    }
    return names;
}

void DriveStatusPoller::skipIfGone(int slave)
{
    // A deleted session never answers: the cycle must not wait for it.
    if (!m_busy || slave != m_current || m_drives->session(slave) == m_currentSession)
        return;
    ++m_generation;
    pollNext();
}

void DriveStatusPoller::start()
{
    if (m_active)
        return;
    m_active = true;
    ++m_generation;
    m_busy = false;
    startCycle();
}

void DriveStatusPoller::stop()
{
    m_active = false;
    ++m_generation; // the poll under way is dropped
    m_busy = false;
    m_queue.clear();
    m_timer.stop();
}

void DriveStatusPoller::pollNow()
{
    if (!m_active)
        return;
    if (m_busy) {
        m_pollAgain = true;
        return;
    }
    m_timer.stop();
    startCycle();
}

void DriveStatusPoller::afterFreshCycle(QObject* context, std::function<void()> then, int limitMs)
{
    if (!m_active) {
        then();
        return;
    }
    // The cycle under way (if any) began before this call: the fresh one is the next after it.
    auto waitFor = std::make_shared<int>(m_busy ? 2 : 1);
    auto done = std::make_shared<bool>(false);
    auto finish = [done, then = std::move(then)] {
        if (*done)
            return;
        *done = true;
        then();
    };
    auto connection = std::make_shared<QMetaObject::Connection>();
    *connection = connect(this, &DriveStatusPoller::cycleFinished, context,
                          [connection, waitFor, finish, context] {
                              if (--*waitFor > 0)
                                  return;
                              QObject::disconnect(*connection);
                              // Not from inside the emit: what follows may delete this poller (a
                              // disconnect tears the bus down).
                              QMetaObject::invokeMethod(context, finish, Qt::QueuedConnection);
                          });
    QTimer::singleShot(limitMs, context, [connection, finish] {
        QObject::disconnect(*connection);
        finish();
    });
    pollNow();
}

void DriveStatusPoller::startCycle()
{
    if (!m_active || m_busy)
        return;
    m_busy = true;
    m_pollAgain = false;
    m_cycleStartMs = QDateTime::currentMSecsSinceEpoch();
    m_queue = m_drives->slaves();
    pollNext();
}

void DriveStatusPoller::pollNext()
{
    while (!m_queue.isEmpty()) {
        const int slave = m_queue.takeFirst();
        if (m_drives->session(slave)) {
            pollDrive(slave);
            return;
        }
    }
    m_busy = false;
    m_current = 0;
    m_currentSession = nullptr;
    ++m_cycles;
    emit cycleFinished();
    scheduleNext();
}

void DriveStatusPoller::pollDrive(int slave)
{
    m_current = slave;
    m_currentSession = m_drives->session(slave);
    const QStringList names = parametersFor(slave);
    const quint64 generation = m_generation;
    if (names.isEmpty()) { // a family with none of these roles: nothing to show but "online"
        DriveStatus s = m_status.value(slave);
        s.polled = true;
        driveDone(slave, s);
        return;
    }
    m_drives->session(slave)->readMany(
        names,
        [this, slave, generation](const DeviceSession::ReadManyOutcome& o) {
            if (generation != m_generation)
                return;
            DeviceSession* session = m_drives->session(slave);
            const Profile& profile = session->profile();
            DriveStatus s = m_status.value(slave);
            s.polled = true;
            QHash<QString, double> raw;
            QStringList errors;
            for (const QString& name : o.order) {
                const DeviceSession::Outcome r = o.results.value(name);
                if (r.value.valid)
                    raw.insert(name, r.value.raw);
                else
                    errors << r.error;
            }
            if (!errors.isEmpty()) {
                ++s.consecutiveFailures;
                s.error = errors.first();
                driveDone(slave, s);
                return;
            }
            s.answered = true;
            s.lastAnswer = QDateTime::currentDateTimeUtc();
            s.consecutiveFailures = 0;
            s.error.clear();
            const auto lookup = [&raw](const QString& n) {
                const auto it = raw.constFind(n);
                return it == raw.cend() ? std::nullopt : std::optional<double>(*it);
            };
            s.running = RoleEvaluator::flag(profile, kRunning, lookup);
            s.alarmActive = RoleEvaluator::flag(profile, kAlarmActive, lookup);
            s.reverse = RoleEvaluator::flag(profile, kReverse, lookup);
            s.motionPriority = RoleEvaluator::holds(profile, kPriority, lookup);
            if (const ParameterMeta* p = RoleEvaluator::parameter(profile, kPriority))
                s.priorityText =
                    ValueCodec::format(*p, o.results.value(p->name).value, session->context());
            const bool needAlarm = s.alarmActive.value_or(false) && !s.alarmCode &&
                                   !profile.records(kAlarmTable).isEmpty();
            if (!s.alarmActive.value_or(false)) {
                s.alarmCode.reset();
                s.alarm.reset();
            }
            m_status.insert(slave, s);
            if (needAlarm)
                readAlarm(slave, generation);
            else
                driveDone(slave, s);
        },
        ModbusRequest::Priority::Poll);
}

void DriveStatusPoller::readAlarm(int slave, quint64 generation)
{
    // The drive says that an alarm is active, not which: the newest record is the one.
    DeviceSession* session = m_drives->session(slave);
    const ParameterMeta* newest = session->profile().records(kAlarmTable).first();
    session->readMany(
        {newest->name},
        [this, slave, generation, newest](const DeviceSession::ReadManyOutcome& o) {
            if (generation != m_generation)
                return;
            DriveStatus s = m_status.value(slave);
            const DeviceSession::Outcome r = o.results.value(newest->name);
            if (r.ok) {
                s.alarmCode = qint64(r.value.raw);
                const CodeTable* table = m_currentSession->profile().codeTable(kAlarmTable);
                if (const CodeEntry* e = table ? table->find(*s.alarmCode) : nullptr)
                    s.alarm = *e;
            }
            driveDone(slave, s);
        },
        ModbusRequest::Priority::Poll);
}

void DriveStatusPoller::driveDone(int slave, const DriveStatus& status)
{
    DriveStatus s = status;
    const DeviceSession* session = m_drives->session(slave);
    applyLed(&s, session ? &session->profile() : nullptr);
    m_status.insert(slave, s);
    emit statusChanged(slave);
    pollNext();
}

void DriveStatusPoller::scheduleNext()
{
    if (!m_active)
        return;
    if (m_pollAgain) {
        m_timer.start(0);
        return;
    }
    const qint64 elapsed = QDateTime::currentMSecsSinceEpoch() - m_cycleStartMs;
    m_timer.start(int(std::clamp<qint64>(m_intervalMs - elapsed, 0, m_intervalMs)));
}

Freshness::State DriveStatusPoller::freshness(int slave, const QDateTime& now) const
{
    const DriveStatus s = m_status.value(slave);
    // Not polled while a scan holds the bus: not live, however recent.
    const bool held = m_drives->client() && m_drives->client()->isPollingHeld();
    return Freshness::of(s.lastAnswer, now, m_intervalMs,
                         m_drives->linkUp() && !held &&
                             s.consecutiveFailures < DriveStatus::kNoAnswerAfter);
}

DriveStatus::Led DriveStatusPoller::shownLed(int slave, const QDateTime& now) const
{
    const DriveStatus s = m_status.value(slave);
    // A communication error is news in itself (blue), as long as the link is up.
    if (s.led == DriveStatus::Led::Blue && m_drives->linkUp())
        return s.led;
    return freshness(slave, now) == Freshness::State::Live ? s.led : DriveStatus::Led::Grey;
}

void DriveStatusPoller::applyLed(DriveStatus* status, const Profile* profile)
{
    status->led = ledFor(*status);
    const StatusLedEntry* entry =
        profile ? profile->ledEntry(DriveStatus::ledLight(status->led)) : nullptr;
    status->ledEntry = entry ? std::optional<StatusLedEntry>(*entry) : std::nullopt;
}

DriveStatus::Led DriveStatusPoller::ledFor(const DriveStatus& s)
{
    using Led = DriveStatus::Led;
    if (!s.polled)
        return Led::Grey;
    if (s.consecutiveFailures > 0)
        return !s.answered || s.consecutiveFailures >= DriveStatus::kNoAnswerAfter ? Led::Grey
                                                                                   : Led::Blue;
    if (s.alarmActive.value_or(false)) {
        // The code table knows the LED colour of each alarm; the DBU's rules where it does not.
        const QString led = s.alarm ? s.alarm->led : QString();
        if (led == QLatin1String("purple") || (led.isEmpty() && s.alarmCode == kExternalInterrupt))
            return Led::Purple;
        if (led == QLatin1String("blue") || (led.isEmpty() && s.alarmCode == kMemoryError))
            return Led::Blue;
        return Led::Red;
    }
    if (s.running.value_or(false))
        return s.reverse.value_or(false) ? Led::SkyBlue : Led::Orange;
    return Led::Green;
}

} // namespace opentop
