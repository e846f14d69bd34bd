#include "model/monitor/DeviceMonitor.h"

#include "model/profile/RoleEvaluator.h"
#include "model/profile/ValueCodec.h"
#include "model/session/DeviceSession.h"
#include "transport/ModbusClient.h"

#include <QPointer>

namespace opentop {

namespace {

const QString kRunning = QStringLiteral("running");
const QString kAlarmActive = QStringLiteral("alarmActive");
const QString kAlarmTable = QStringLiteral("alarm");

} // namespace

const MonitorValue* MonitorSample::find(const QString& parameter) const
{
    for (const MonitorValue& v : values) {
        if (v.meta && v.meta->name == parameter)
            return &v;
    }
    return nullptr;
}

std::optional<double> MonitorSample::rawOf(const QString& parameter) const
{
    const MonitorValue* v = find(parameter);
    return v && v->value.valid ? std::optional<double>(v->value.raw) : std::nullopt;
}

std::optional<double> MonitorSample::signedSpeed(const QString& parameter) const
{
    const MonitorValue* speed = find(parameter);
    if (!speed || !speed->value.valid)
        return std::nullopt;
    double number = speed->value.number;
    // A register that holds the magnitude only: the status bits tell the direction.
    if (reverse.value_or(false) && number > 0)
        number = -number;
    return number;
}

QString MonitorSample::signedText(const QString& parameter) const
{
    const MonitorValue* v = find(parameter);
    const std::optional<double> number = signedSpeed(parameter);
    if (!v || !v->meta || !number)
        return QString();
    // Only a magnitude made negative needs new text; everything else keeps the codec's.
    if (*number >= 0 || v->value.number < 0 || !v->meta->spec.options.isEmpty())
        return v->text;
    const QString digits = QString::number(*number, 'f', v->meta->spec.decimals);
    return v->meta->spec.unit.isEmpty() ? digits
                                        : QStringLiteral("%1 %2").arg(digits, v->meta->spec.unit);
}

QString MonitorSample::stateText() const
{
    if (!running)
        return QString();
    if (!*running)
        return DeviceMonitor::tr("Stopped");
    if (!reverse)
        return DeviceMonitor::tr("Running");
    return *reverse ? DeviceMonitor::tr("Running CCW") : DeviceMonitor::tr("Running CW");
}

struct DeviceMonitor::Poll
{
    quint64 generation = 0;
    QDateTime timestamp;
    QHash<QString, ParamValue> values;
    QStringList errors;
};

DeviceMonitor::DeviceMonitor(DeviceSession* session, QObject* parent)
    : QObject(parent)
    , m_session(session)
{
    const Profile& profile = session->profile();
    if (const ProfileRole* role = profile.role(QStringLiteral("monitor")))
        m_names = role->parameters.isEmpty() && !role->parameter.isEmpty()
                      ? QStringList{role->parameter}
                      : role->parameters;
    for (const QString& role : {kRunning, kAlarmActive}) {
        const ParameterMeta* meta = RoleEvaluator::parameter(profile, role);
        if (meta && meta->isReadable() && !m_names.contains(meta->name))
            m_names << meta->name;
    }
    m_timer.setSingleShot(true);
    m_timer.setTimerType(Qt::PreciseTimer); // samples at the interval, not about it
    connect(&m_timer, &QTimer::timeout, this, &DeviceMonitor::poll);
}

DeviceMonitor::~DeviceMonitor()
{
    stop();
}

void DeviceMonitor::prepare(std::function<void(const QString&)> done)
{
    const SpeedDisplay::Names names = SpeedDisplay::Names::withPrefix();
    if (!SpeedDisplay::supported(m_session->profile(), names)) {
        m_display.reset();
        done(QString());
        return;
    }
    // The monitor may be gone when the answer comes (its view closed): the guard drops it.
    m_session->readMany(names.all(), [this, self = QPointer<DeviceMonitor>(this), names,
                                      done](const DeviceSession::ReadManyOutcome& o) {
        if (!self)
            return;
        QString error;
        m_display = SpeedDisplay::fromValues(
            names,
            [&o](const QString& name) -> std::optional<double> {
                const DeviceSession::Outcome r = o.results.value(name);
                return r.value.valid ? std::optional<double>(r.value.number) : std::nullopt;
            },
            &error);
        done(error);
    });
}

void DeviceMonitor::start()
{
    if (m_active)
        return;
    m_active = true;
    ++m_generation;
    m_busy = false;
    poll();
}

void DeviceMonitor::stop()
{
    m_active = false;
    ++m_generation; // results of the poll under way are dropped
    m_busy = false;
    m_timer.stop();
}

void DeviceMonitor::poll()
{
    if (!m_active || m_busy)
        return;
    m_busy = true;
    m_pollClock.restart();
    auto p = std::make_shared<Poll>();
    p->generation = m_generation;
    p->timestamp = QDateTime::currentDateTime();
    m_session->readMany(
        m_names,
        [this, self = QPointer<DeviceMonitor>(this), p](const DeviceSession::ReadManyOutcome& o) {
            if (!self || p->generation != m_generation)
                return; // gone, stopped or restarted meanwhile
            for (const QString& name : o.order) {
                const DeviceSession::Outcome r = o.results.value(name);
                if (r.value.valid)
                    p->values.insert(name, r.value);
                else
                    p->errors << QStringLiteral("%1: %2").arg(name, r.error);
            }
            pollDone(p);
        },
        ModbusRequest::Priority::Poll);
}

void DeviceMonitor::pollDone(const std::shared_ptr<Poll>& p)
{
    const Profile& profile = m_session->profile();
    const std::optional<bool> alarm =
        RoleEvaluator::flag(profile, kAlarmActive, [&p](const QString& n) {
            const auto it = p->values.constFind(n);
            return it == p->values.cend() ? std::nullopt : std::optional<double>(it->raw);
        });
    if (!alarm.value_or(false))
        m_activeAlarmCode.reset();
    else if (!m_activeAlarmCode && p->errors.isEmpty() && !profile.records(kAlarmTable).isEmpty()) {
        readActiveAlarm(p);
        return;
    }
    finish(p);
}

void DeviceMonitor::readActiveAlarm(const std::shared_ptr<Poll>& p)
{
    // The drive reports that an alarm is active, not which: the newest record is the one.
    const ParameterMeta* newest = m_session->profile().records(kAlarmTable).first();
    m_session->readMany(
        {newest->name},
        [this, self = QPointer<DeviceMonitor>(this), p,
         newest](const DeviceSession::ReadManyOutcome& o) {
            if (!self || p->generation != m_generation)
                return;
            const DeviceSession::Outcome r = o.results.value(newest->name);
            if (r.ok)
                m_activeAlarmCode = qint64(r.value.raw);
            finish(p);
        },
        ModbusRequest::Priority::Poll);
}

void DeviceMonitor::finish(const std::shared_ptr<Poll>& p)
{
    m_busy = false;
    if (!p->errors.isEmpty()) {
        emit error(tr("machine number %1: %2")
                       .arg(m_session->slave())
                       .arg(p->errors.join(QStringLiteral("; "))));
    } else {
        const MonitorSample s = buildSample(*p);
        emit sample(s.timestamp, s);
    }
    scheduleNext();
}

void DeviceMonitor::setInterval(int ms)
{
    if (ms == m_intervalMs)
        return;
    m_intervalMs = ms;
    // Waiting for the next poll: it is due by the new interval (a view coming into sight wants
    // its values now, not at the end of a recording drive's slow second).
    if (m_active && !m_busy && m_timer.isActive())
        scheduleNext();
}

void DeviceMonitor::scheduleNext()
{
    if (!m_active)
        return;
    const qint64 elapsed = m_pollClock.isValid() ? m_pollClock.elapsed() : 0;
    m_timer.start(int(std::max<qint64>(0, m_intervalMs - elapsed)));
}

MonitorSample DeviceMonitor::buildSample(const Poll& p) const
{
    const Profile& profile = m_session->profile();
    const ValueContext context = m_session->context();
    MonitorSample s;
    s.slave = m_session->slave();
    s.timestamp = p.timestamp;
    for (const QString& name : m_names) {
        MonitorValue v;
        v.meta = profile.parameter(name);
        v.value = p.values.value(name);
        if (v.meta)
            v.text = ValueCodec::format(*v.meta, v.value, context);
        s.values << v;
    }
    const auto raw = [&p](const QString& n) {
        const auto it = p.values.constFind(n);
        return it == p.values.cend() ? std::nullopt : std::optional<double>(it->raw);
    };
    s.running = RoleEvaluator::flag(profile, kRunning, raw);
    s.alarmActive = RoleEvaluator::flag(profile, kAlarmActive, raw);
    s.reverse = RoleEvaluator::flag(profile, QStringLiteral("reverse"), raw);
    if (s.alarmActive.value_or(false) && m_activeAlarmCode) {
        s.activeAlarmCode = m_activeAlarmCode;
        const CodeTable* table = profile.codeTable(kAlarmTable);
        if (const CodeEntry* e = table ? table->find(*m_activeAlarmCode) : nullptr)
            s.activeAlarm = *e;
    }
    if (m_display) {
        for (const auto& [role, shown] :
             {std::make_pair(QStringLiteral("currentSpeed"), &s.currentShown),
              std::make_pair(QStringLiteral("targetSpeed"), &s.targetShown)}) {
            const ParameterMeta* meta = RoleEvaluator::parameter(profile, role);
            const std::optional<double> speed = meta ? s.signedSpeed(meta->name) : std::nullopt;
            if (speed)
                *shown = m_display->show(*speed);
        }
    }
    return s;
}

} // namespace opentop
