#include "sim/DbuSimDevice.h"

#include "sim/SimLog.h"

#include <QRegularExpression>
#include <algorithm>
#include <cmath>

namespace opentop {

namespace {

// Communication error codes kept in 0x007B (manual 11-5).
constexpr int kErrFunctionOrAddress = 0xE0;
constexpr int kErrFormat = 0xE1;
constexpr int kErrCannotExecute = 0xE2;
constexpr int kErrBusy = 0xE3;
constexpr int kErrRange = 0xE8;

constexpr double kFullScaleRpm = 3000; // acceleration times are for 0 <-> 3000 r/min
constexpr double kVrRampSeconds = 1.0; // SS/SD potentiometers, used by SPno1
constexpr int kAlarmExternal = 0x0F;

const int kRates[] = {9600, 14400, 19200, 28800, 38400, 57600, 115200};

QString spno(int index, const char* field)
{
    return QStringLiteral("spno%1.%2").arg(index + 1).arg(QLatin1String(field));
}

} // namespace

DbuSimDevice::DbuSimDevice(const Profile& profile, const QString& variant, int slave)
    : SimDevice(profile, variant, slave)
    , m_alarms(this, QStringLiteral("alarm"))
    , m_warnings(this, QStringLiteral("warning"))
    , m_terminals(*this)
{
    if (const ParameterMeta* name = param(QStringLiteral("info.device_name"))) {
        const QString text = name->spec.defaultText;
        registers().setText(*name, text.isEmpty() ? QStringLiteral("DBU") : text, ' ');
    }
    if (rawOf(QStringLiteral("info.version")) == 0)
        setRawOf(QStringLiteral("info.version"), 0x0105);
    if (const std::optional<double> vr = raw(QStringLiteral("spno1.speed")); vr && *vr > 0)
        m_vr = int(*vr);
    m_activeRate = int(rawOf(QStringLiteral("comm.rate")));
    refreshStatus(0);
}

int DbuSimDevice::baudForRateCode(int code)
{
    return code >= 0 && code < int(std::size(kRates)) ? kRates[code] : 0;
}

std::optional<int> DbuSimDevice::groupAddress() const
{
    const int group = int(rawOf(QStringLiteral("comm.group")));
    if (group >= 1 && group <= 247)
        return group;
    return std::nullopt;
}

int DbuSimDevice::lineBaud() const
{
    return baudForRateCode(m_activeRate);
}

void DbuSimDevice::configureLine(int baud, char)
{
    for (int code = 0; code < int(std::size(kRates)); ++code) {
        if (kRates[code] == baud) {
            setRawOf(QStringLiteral("comm.rate"), code);
            m_activeRate = code;
        }
    }
}

bool DbuSimDevice::supportsFunction(quint8 function) const
{
    return function == 0x03 || function == 0x04 || function == 0x06 || function == 0x10;
}

quint8 DbuSimDevice::exceptionCode(SimError error) const
{
    switch (error) {
    case SimError::IllegalFunction:
        return 0x01;
    case SimError::IllegalAddress:
        return 0x02;
    case SimError::BadFormat:
        return 0x03;
    default:
        return 0x04;
    }
}

void DbuSimDevice::recordError(SimError error)
{
    SimDevice::recordError(error);
    int code = kErrCannotExecute;
    switch (error) {
    case SimError::IllegalFunction:
    case SimError::IllegalAddress:
        code = kErrFunctionOrAddress;
        break;
    case SimError::BadFormat:
        code = kErrFormat;
        break;
    case SimError::Busy:
        code = kErrBusy;
        break;
    case SimError::OutOfRange:
        code = kErrRange;
        break;
    default:
        break;
    }
    setRawOf(QStringLiteral("status.comm_error"), code);
}

bool DbuSimDevice::communicationControl() const
{
    return !m_offline && rawOf(QStringLiteral("core.control_priority")) == 2;
}

DbuSimDevice::Command DbuSimDevice::currentCommand() const
{
    Command c;
    if (communicationControl()) {
        c.run = m_started;
        c.spno = std::clamp(int(rawOf(QStringLiteral("run.select"))), 0, 7);
        c.ccw =
            m_directionOverride ? *m_directionOverride == 1 : rawOf(spno(c.spno, "direction")) == 1;
        return c;
    }
    const DbuTerminals::IoCommand io = m_terminals.command(m_inputs);
    c.run = io.run;
    c.spno = io.spno;
    c.ccw = io.ccw.value_or(rawOf(spno(c.spno, "direction")) == 1);
    return c;
}

double DbuSimDevice::targetMagnitude(const Command& command) const
{
    if (!command.run || m_alarm)
        return 0;
    const double set = command.spno == 0 ? m_vr : rawOf(spno(command.spno, "speed"));
    if (set <= 0)
        return 0;
    const double upper = rawOf(QStringLiteral("core.upper_limit"));
    const double lower = rawOf(QStringLiteral("core.lower_limit"));
    return std::min(std::max(set, lower), upper);
}

double DbuSimDevice::rampRate(int index, bool accelerate) const
{
    double seconds = kVrRampSeconds;
    if (index > 0) {
        const ParameterMeta* p = param(spno(index, accelerate ? "accel" : "decel"));
        if (p)
            seconds = rawOf(p->name) * p->specFor(context()).scale;
    }
    return kFullScaleRpm / std::max(seconds, 0.1);
}

void DbuSimDevice::step(qint64, int dtMs)
{
    if (!communicationControl()) {
        const int rising =
            m_terminals.assigned(DbuTerminals::AlarmReset) & m_inputs & ~m_previousInputs;
        if (rising && m_alarm && alarmResettable())
            m_alarm = 0;
    }
    m_previousInputs = m_inputs;
    const int extError = m_terminals.assigned(DbuTerminals::ExtError);
    if (extError && (extError & m_inputs) != extError)
        raiseAlarm(kAlarmExternal);

    m_command = currentCommand();
    const double magnitude = targetMagnitude(m_command);
    m_target = m_command.ccw ? -magnitude : magnitude;
    if (m_alarm)
        return;
    DbuMotor::Input in;
    in.target = m_target;
    in.defects = &defects();
    in.accelPerSecond = rampRate(m_command.spno, true);
    in.decelPerSecond = rampRate(m_command.spno, false);
    in.commanded = magnitude > 0;
    if (const ParameterMeta* p = param(QStringLiteral("alarm.overload_time")))
        in.overloadMs = rawOf(p->name) * p->specFor(context()).scale * 1000;
    in.loadWarning = rawOf(QStringLiteral("alarm.load_warning"));
    in.loadOffset = m_loadOffset;
    const DbuMotor::Events events = m_motor.step(in, dtMs);
    for (int code : events.warnings)
        m_warnings.push(code);
    if (events.alarm)
        raiseAlarm(events.alarm);
}

bool DbuSimDevice::quiescent() const
{
    // Stopped with nothing commanded: every step until the next frame would change nothing.
    return m_motor.speed() == 0 && m_target == 0 && !m_started;
}

void DbuSimDevice::raiseAlarm(int code)
{
    if (m_alarm)
        return;
    m_alarm = code;
    m_started = false;
    m_motor.stop();
    m_alarms.push(code);
    qCInfo(lcSim) << "slave" << slave() << "alarm" << Qt::hex << code;
}

bool DbuSimDevice::alarmResettable() const
{
    if (!m_alarm)
        return true;
    const CodeEntry* entry = m_alarms.find(m_alarm);
    return rawOf(QStringLiteral("core.alarm_erase")) == 1 && entry &&
           entry->reset == QLatin1String("alarm-reset");
}

void DbuSimDevice::refreshStatus(qint64)
{
    m_command = currentCommand();
    const double speed = std::abs(m_motor.speed());
    const bool running = (m_command.run && m_target != 0) || speed > 0;
    const bool ccw = m_motor.speed() < 0 || (m_motor.speed() == 0 && m_command.ccw);
    const bool holding = !running && !m_alarm && rawOf(QStringLiteral("run.hold")) == 0;
    quint32 bits = 0;
    bits |= running ? 1u << 1 : 0;
    bits |= ccw ? 1u << 2 : 0;
    bits |= holding ? 1u << 4 : 0;
    bits |= quint32(m_command.spno & 7) << 8;
    bits |= m_alarm ? 1u << 11 : 0;
    bits |= rawOf(QStringLiteral("core.control_mode")) == 1 ? 1u << 12 : 0;
    setRawOf(QStringLiteral("status.driver"), bits);
    setRawOf(QStringLiteral("status.current_speed"), std::round(speed));
    setRawOf(QStringLiteral("status.target_speed"), std::round(std::abs(m_target)));
    setRawOf(QStringLiteral("status.load"), std::round(m_motor.load()));
    setRawOf(QStringLiteral("status.inputs"), m_inputs);
    DbuTerminals::State out;
    out.alarm = m_alarm != 0;
    out.reach = m_command.run && m_target != 0 && speed == std::abs(m_target);
    out.va = m_command.run && m_target != 0 &&
             speed >= std::abs(m_target) - rawOf(QStringLiteral("va.speed"));
    out.warning = m_motor.warningActive() || m_consoleWarning;
    out.speed = speed;
    out.revolutions = m_motor.revolutions();
    setRawOf(QStringLiteral("status.outputs"), m_terminals.outputs(out));
    setRawOf(QStringLiteral("spno1.speed"), m_vr);
}

SimError DbuSimDevice::checkWrite(const ParameterMeta& meta, double raw, qint64)
{
    const QString& n = meta.name;
    if (n == QLatin1String("run.start") || n == QLatin1String("run.direction") ||
        n == QLatin1String("run.select") || n == QLatin1String("run.hold")) {
        if (!communicationControl())
            return SimError::Refused;
        if (n == QLatin1String("run.start") && raw == 1 && m_alarm)
            return SimError::Refused;
    } else if (n == QLatin1String("cmd.alarm_reset")) {
        if (!alarmResettable())
            return SimError::Refused;
    } else if (n == QLatin1String("cmd.param_init")) {
        if (m_started || m_motor.speed() != 0)
            return SimError::Refused;
    }
    return SimError::None;
}

void DbuSimDevice::afterWrite(const ParameterMeta& meta, double raw, qint64 nowMs)
{
    SimDevice::afterWrite(meta, raw, nowMs);
    const QString& n = meta.name;
    static const QRegularExpression spnoField(QStringLiteral("^spno([1-8])\\.(\\w+)$"));
    const QRegularExpressionMatch m = spnoField.match(n);
    if (n == QLatin1String("run.start")) {
        if (raw == 1)
            m_started = true;
        else if (!m_ignoreStop)
            m_started = false;
    } else if (n == QLatin1String("run.direction")) {
        m_directionOverride = int(raw);
    } else if (n == QLatin1String("run.select")) {
        m_directionOverride.reset();
    } else if (n == QLatin1String("cmd.alarm_reset")) {
        m_alarm = 0;
    } else if (n == QLatin1String("cmd.erase_alarms")) {
        m_alarms.clear();
    } else if (n == QLatin1String("cmd.erase_warnings")) {
        m_warnings.clear();
    } else if (n == QLatin1String("cmd.param_init")) {
        for (const ParameterMeta& p : profile().parameters) {
            if (p.kind == QLatin1String("setting"))
                applyDefault(p);
        }
        m_directionOverride.reset();
    } else if (m.hasMatch() && m.captured(2) == QLatin1String("init")) {
        const QString prefix = QStringLiteral("spno%1.").arg(m.captured(1));
        for (const ParameterMeta& p : profile().parameters) {
            if (p.name.startsWith(prefix) && p.kind == QLatin1String("setting"))
                applyDefault(p);
        }
    } else if (m.hasMatch() && m.captured(2) == QLatin1String("direction")) {
        if (m.captured(1).toInt() - 1 == int(rawOf(QStringLiteral("run.select"))))
            m_directionOverride.reset();
    } else if (n == QLatin1String("cmd.connect")) {
        m_offline = false;
    } else if (n == QLatin1String("cmd.offline")) {
        m_offline = true;
        m_started = false;
    } else if (n == QLatin1String("core.control_priority") && raw != 2) {
        m_started = false;
    }
}

void DbuSimDevice::onPowerCycle(qint64)
{
    m_motor.reset();
    m_target = 0;
    m_command = {};
    m_started = false;
    m_offline = false;
    m_alarm = 0;
    m_directionOverride.reset();
    m_consoleWarning = 0;
    m_previousInputs = m_inputs;
    m_activeRate = int(rawOf(QStringLiteral("comm.rate")));
}

QString DbuSimDevice::stateText() const
{
    QString state = m_alarm ? tr("alarm 0x%1").arg(m_alarm, 2, 16, QLatin1Char('0'))
                    : m_motor.speed() != 0 || m_command.run ? tr("running")
                                                            : tr("stopped");
    return tr("%1 %2 r/min (target %3) SPno%4 load %5 % %6, %7 priority, %8%9")
        .arg(type(), QString::number(std::lround(m_motor.speed())),
             QString::number(std::lround(m_target)), QString::number(m_command.spno + 1),
             QString::number(std::lround(m_motor.load())), state,
             rawOf(QStringLiteral("core.control_priority")) == 2 ? tr("communication") : tr("I/O"),
             m_offline ? tr("offline") : tr("online"),
             m_ignoreStop ? tr(", ignoring stop") : QString());
}

SimControlResult DbuSimDevice::consoleCode(const QStringList& args, bool alarm)
{
    const QString what = alarm ? QStringLiteral("alarm") : QStringLiteral("warning");
    const std::optional<qint64> code = args.size() == 2 ? parseNumber(args.at(1)) : std::nullopt;
    if (!code)
        return fail(tr("usage: %1 ID CODE").arg(what));
    if (!alarm && *code == 0) {
        m_consoleWarning = 0;
        return {true, tr("warning cleared")};
    }
    SimCodeRecords& records = alarm ? m_alarms : m_warnings;
    if (records.table() && !records.find(int(*code)))
        return fail(
            tr("unknown %1 code %2; allowed: %3").arg(what, args.at(1), records.codesText()));
    if (alarm) {
        m_alarm = 0; // a new alarm replaces the active one
        raiseAlarm(int(*code));
    } else {
        m_warnings.push(int(*code));
        m_consoleWarning = int(*code);
    }
    return {true, tr("%1 0x%2 raised").arg(what).arg(*code, 2, 16, QLatin1Char('0'))};
}

SimControlResult DbuSimDevice::controlCommand(const QStringList& args, qint64 nowMs)
{
    const QString& cmd = args.first();
    if (cmd == QLatin1String("alarm") || cmd == QLatin1String("warning"))
        return consoleCode(args, cmd == QLatin1String("alarm"));
    if (cmd == QLatin1String("ignore-stop")) {
        if (args.size() != 2 ||
            (args.at(1) != QLatin1String("on") && args.at(1) != QLatin1String("off")))
            return fail(tr("usage: ignore-stop ID on|off"));
        m_ignoreStop = args.at(1) == QLatin1String("on");
        return {true, m_ignoreStop ? tr("stop commands are acknowledged and ignored")
                                   : tr("stop commands are obeyed")};
    }
    struct Range
    {
        const char* name;
        qint64 min;
        qint64 max;
        int* target;
    };
    const Range ranges[] = {
        {"load", -200, 200, &m_loadOffset}, {"vr", 0, 4000, &m_vr}, {"input", 0, 15, &m_inputs}};
    for (const Range& r : ranges) {
        if (cmd != QLatin1String(r.name))
            continue;
        const std::optional<qint64> v = args.size() == 2 ? parseNumber(args.at(1)) : std::nullopt;
        if (!v || *v < r.min || *v > r.max)
            return fail(tr("usage: %1 ID VALUE with VALUE %2..%3").arg(cmd).arg(r.min).arg(r.max));
        *r.target = int(*v);
        return {true, tr("%1 = %2").arg(cmd).arg(*v)};
    }
    return SimDevice::controlCommand(args, nowMs);
}

} // namespace opentop
