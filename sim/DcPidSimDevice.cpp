#include "sim/DcPidSimDevice.h"

#include "model/profile/ValueCodec.h"
#include "sim/SimLog.h"
#include "transport/DeviceIdentification.h"
#include "transport/ModbusRequest.h"

#include <algorithm>
#include <cmath>

namespace opentop {

namespace {

constexpr double kStoppedCommutation = 0.5; // below this the shaft counts as stopped

struct StoreBlock
{
    const char* first; // first parameter of the block
    int count;         // registers a 0x10 must write to store the block
};

// "0x10 of 15 registers from 0x0080", 7 from 0x0090, 4 from 0x00A0, 5 from 0x0050.
const StoreBlock kBlocks[] = {
    {"config.speed_mode", 15}, {"pid.p", 7}, {"preset.speed_mode", 4}, {"gpio.ai1_direction", 5}};

// Values the profile gives no default for (the manual names none): a plausible factory state.
struct Factory
{
    const char* name;
    double raw;
};
const Factory kFactory[] = {{"info.device_id", 1},
                            {"info.version", 0x0100},
                            {"info.pwm_resolution", 1000},
                            {"info.pwm_frequency", 16000},
                            {"info.max_current", 2000},
                            {"info.current_resolution", 10},
                            {"config.rated_current", 500},
                            {"config.max_current", 1000},
                            {"config.brake_current", 200},
                            {"pid.p", 0.1},
                            {"pid.i", 0.01},
                            {"pid.d", 0},
                            {"pid.d_period", 10},
                            {"preset.forward_speed", 500},
                            {"preset.reverse_speed", 500}};
const char* const kGpio[] = {"gpio.ai1_direction", "gpio.ai2_direction", "gpio.ai1_level",
                             "gpio.ai2_level"};

QString name(const char* text)
{
    return QString::fromLatin1(text);
}

} // namespace

DcPidSimDevice::DcPidSimDevice(const Profile& profile, const QString& variant, int slave)
    : SimDevice(profile, variant, slave)
{
    for (const Factory& f : kFactory) {
        const ParameterMeta* p = param(name(f.name));
        if (p && !p->specFor(context()).defaultRaw)
            registers().setRaw(*p, f.raw);
    }
    if (const ParameterMeta* p = param(QStringLiteral("info.device_name")))
        registers().setText(*p, QStringLiteral("DCPID-20A"), '\0');
    for (const char* store : {"store.config", "store.pid", "store.preset"})
        registers().storeGroup(name(store));
    for (const char* n : kGpio) {
        if (const ParameterMeta* p = param(name(n)))
            registers().storeParameter(*p); // GPIO is temporary until a 5-register write
    }
    takeLineSettings();
    refreshStatus(0);
}

char DcPidSimDevice::parityForCode(int code)
{
    return code == 1 ? 'O' : code == 2 ? 'E' : 'N';
}

void DcPidSimDevice::takeLineSettings()
{
    m_lineBaud = int(rawOf(QStringLiteral("config.baud")));
    m_lineParity = parityForCode(int(rawOf(QStringLiteral("config.parity"))));
}

void DcPidSimDevice::configureLine(int baud, char parity)
{
    setRawOf(QStringLiteral("config.baud"), baud);
    setRawOf(QStringLiteral("config.parity"), parity == 'O' ? 1 : parity == 'E' ? 2 : 0);
    for (const char* n : {"config.baud", "config.parity"}) {
        if (const ParameterMeta* p = param(name(n)))
            registers().storeParameter(*p);
    }
    takeLineSettings();
}

bool DcPidSimDevice::supportsFunction(quint8 function) const
{
    return function == 0x03 || function == 0x06 || function == 0x10 || function == 0x2B;
}

quint8 DcPidSimDevice::exceptionCode(SimError error) const
{
    // The controller's extended code 0x40 "prohibited action" (manual 1.2.4.2).
    return error == SimError::Prohibited ? 0x40 : SimDevice::exceptionCode(error);
}

bool DcPidSimDevice::allowsPartialWrite(const ParameterMeta& meta) const
{
    return meta.registerCount > 1; // PID floats and the baud rate by halves (06)
}

bool DcPidSimDevice::acceptsGapWrite(quint16 address) const
{
    return registers().inReadBlock(3, address); // reserved registers inside the blocks
}

SimError DcPidSimDevice::checkWrite(const ParameterMeta& meta, double raw, qint64)
{
    const bool serial =
        meta.name == QLatin1String("config.baud") || meta.name == QLatin1String("config.parity");
    if (serial && rawOf(QStringLiteral("config.serial_lock")) == 1 && raw != rawOf(meta.name))
        return SimError::Prohibited;
    return SimError::None;
}

void DcPidSimDevice::afterWrite(const ParameterMeta& meta, double raw, qint64 nowMs)
{
    const QString& n = meta.name;
    if (n == QLatin1String("speed.command")) {
        m_command = int(raw);
        m_stallStopped = false;
        m_drive = m_command == 0 ? Drive::Braking : Drive::Running;
    } else if (n == QLatin1String("speed.lock")) {
        m_command = 0;
        m_drive = Drive::Locked;
    } else if (n == QLatin1String("speed.release")) {
        m_command = 0;
        m_drive = Drive::Coasting;
    } else if (n == QLatin1String("store.config") && raw == 0) {
        registers().reloadGroup(n);
    } else {
        SimDevice::afterWrite(meta, raw, nowMs);
    }
}

void DcPidSimDevice::afterBlockWrite(quint8 function, quint16 address, int count, qint64)
{
    if (function != ModbusRequest::WriteMultiple)
        return;
    for (const StoreBlock& b : kBlocks) {
        const ParameterMeta* first = param(name(b.first));
        if (!first || first->address != address || count != b.count)
            continue;
        qCDebug(lcSim) << "slave" << slave() << "stores the block of" << b.first;
        if (!first->storeWith.isEmpty()) {
            registers().storeGroup(first->storeWith);
            continue;
        }
        for (const char* n : kGpio) {
            if (const ParameterMeta* p = param(name(n)))
                registers().storeParameter(*p);
        }
    }
}

DcSpeedLoop::Gains DcPidSimDevice::gains() const
{
    DcSpeedLoop::Gains g;
    g.p = rawOf(QStringLiteral("pid.p"));
    g.i = rawOf(QStringLiteral("pid.i"));
    g.d = rawOf(QStringLiteral("pid.d"));
    g.dPeriodMs = int(rawOf(QStringLiteral("pid.d_period")));
    return g;
}

void DcPidSimDevice::step(qint64 nowMs, int dtMs)
{
    const double lossMs = rawOf(QStringLiteral("config.comm_loss_time")) * 100;
    if (m_drive == Drive::Running && lossMs > 0 && nowMs - m_lastFrameMs >= lossMs) {
        qCInfo(lcSim) << "slave" << slave() << "communication lost: braking";
        m_drive = Drive::Braking;
        m_command = 0;
    }
    for (int ms = 0; ms < dtMs; ++ms)
        stepMotor();
    stallProtection(dtMs);
    if (m_drive != Drive::Running && m_drive != Drive::Locked &&
        std::abs(m_motor.commutation()) < kStoppedCommutation)
        m_drive = Drive::Idle;
}

void DcPidSimDevice::stepMotor()
{
    DcMotor::Input in;
    in.maxCurrentA = rawOf(QStringLiteral("config.max_current")) / 100;
    in.brakeCurrentA = rawOf(QStringLiteral("config.brake_current")) / 100;
    if (defects().stall)
        in.maxCommutation = 0;
    else if (defects().maxSpeed)
        in.maxCommutation = *defects().maxSpeed;
    bool limited = false;
    if (m_drive == Drive::Running && rawOf(QStringLiteral("config.limit_enable")) == 1) {
        const bool sq1 = m_inputs & 1;
        const bool sq2 = m_inputs & 2;
        limited = (m_command > 0 && sq1 == (rawOf(QStringLiteral("config.sq1_level")) == 1)) ||
                  (m_command < 0 && sq2 == (rawOf(QStringLiteral("config.sq2_level")) == 1));
    }
    const int mode = int(rawOf(QStringLiteral("config.speed_mode")));
    if (m_drive == Drive::Running && !limited && m_command != 0) {
        switch (mode) {
        case 1:
            in.drive = DcMotor::Drive::Current;
            in.currentA = m_command / 100.0;
            break;
        case 2:
            in.drive = DcMotor::Drive::Duty;
            in.duty = m_loop.step(m_command, m_motor.measuredCommutation(), gains());
            break;
        case 3:
            in.drive = DcMotor::Drive::Duty;
            in.duty = m_loop.step(m_command, m_motor.tachoVolts() * 100, gains());
            break;
        default:
            in.drive = DcMotor::Drive::Duty;
            in.duty = m_command / 1000.0;
            break;
        }
    } else {
        m_loop.reset();
        in.drive = m_drive == Drive::Coasting ? DcMotor::Drive::Coast
                   : m_drive == Drive::Locked ? DcMotor::Drive::Hold
                   : m_drive == Drive::Idle   ? DcMotor::Drive::Coast
                                              : DcMotor::Drive::Brake;
    }
    m_motor.step(in);
}

double DcPidSimDevice::turning() const
{
    return m_motor.measuredCommutation();
}

void DcPidSimDevice::stallProtection(int dtMs)
{
    const bool running = m_drive == Drive::Running && m_command != 0;
    const SimDefects& defect = defects();
    m_runningMs = running ? m_runningMs + dtMs : 0;
    // The controller's stall stop (config.stall_time): output but no rotation for that time.
    const bool stalled = running && std::abs(m_motor.appliedDuty()) > 0.01 &&
                         std::abs(turning()) < kStoppedCommutation;
    m_stalledMs = stalled ? m_stalledMs + dtMs : 0;
    const double stallMs = rawOf(QStringLiteral("config.stall_time")) * 100;
    const bool defectDue = running && defect.alarmCode && m_runningMs >= defect.alarmAfterMs;
    if ((stallMs > 0 && m_stalledMs >= stallMs) || defectDue) {
        qCInfo(lcSim) << "slave" << slave() << "stall stop: braking";
        m_drive = Drive::Braking;
        m_command = 0;
        m_stallStopped = true;
        m_runningMs = m_stalledMs = 0;
    }
}

void DcPidSimDevice::refreshStatus(qint64)
{
    const SimDefects& defect = defects();
    double current = std::abs(m_motor.currentA()) * 100; // 0.01 A
    current *= defect.loadScale * (1 + (m_loadOffset + defect.loadOffset) / 100.0);
    current = std::max(0.0, current);

    auto put = [this](const char* n, double value) {
        const ParameterMeta* p = param(name(n));
        if (p)
            setRawOf(p->name, p->isSigned() ? value : std::abs(value));
    };
    put("status.pwm", std::round(m_motor.appliedDuty() * 1000));
    put("status.current", std::round(std::min(current, 2000.0)));
    put("status.commutation", std::round(std::min(std::abs(turning()), 2000.0)));
    if (int(rawOf(QStringLiteral("config.speed_mode"))) == 3)
        put("status.ai1_voltage",
            std::round(std::min(std::abs(m_motor.tachoVolts()) * 100, 500.0)));
    put("status.sq1_level", m_inputs & 1);
    put("status.sq2_level", (m_inputs >> 1) & 1);
    put("status.de_level", (m_inputs >> 2) & 1);
    put("status.ai_diff",
        rawOf(QStringLiteral("status.ai1_voltage")) - rawOf(QStringLiteral("status.ai2_voltage")));
}

void DcPidSimDevice::onPowerCycle(qint64 nowMs)
{
    m_motor.reset();
    m_loop.reset();
    m_drive = Drive::Idle;
    m_command = 0;
    m_runningMs = m_stalledMs = 0;
    m_stallStopped = false;
    m_lastFrameMs = nowMs;
    for (const char* n : kGpio) {
        if (const ParameterMeta* p = param(name(n)))
            registers().restoreParameter(*p);
    }
    takeLineSettings();
}

QByteArray DcPidSimDevice::handleOther(const ModbusRequest& request, qint64, SimError* error)
{
    if (request.function != ModbusRequest::EncapsulatedInterface) {
        *error = SimError::IllegalFunction;
        return {};
    }
    const QByteArray& d = request.rawData;
    if (d.size() != 3) {
        *error = SimError::BadFormat;
        return {};
    }
    if (quint8(d.at(0)) != 0x0E) {
        *error = SimError::IllegalFunction;
        return {};
    }
    return identification(quint8(d.at(1)), quint8(d.at(2)), error);
}

QByteArray DcPidSimDevice::identification(quint8 readCode, quint8 objectId, SimError* error) const
{
    // Basic category only: 0 vendor, 1 product code, 2 revision.
    QString product;
    QString revision;
    for (const ParameterMeta& p : profile().parameters) {
        if (!p.name.startsWith(QLatin1String("info.")))
            continue;
        if (p.type == DataType::String && product.isEmpty()) {
            const ParamValue v = ValueCodec::decode(p, registers().registers(p), context());
            product = v.text.trimmed();
        } else if (p.name.contains(QLatin1String("version")) ||
                   p.name.contains(QLatin1String("release"))) {
            const int raw = int(registers().raw(p));
            revision = QStringLiteral("V%1.%2").arg(raw >> 8).arg(raw & 0xFF);
        }
    }
    if (readCode < 1 || readCode > 4) {
        *error = SimError::BadFormat;
        return {};
    }
    if (readCode == 4 && objectId > 2) {
        *error = SimError::IllegalAddress;
        return {};
    }
    const QByteArray objects[] = {profile().vendor.toLatin1(), product.toLatin1(),
                                  revision.toLatin1()};
    DeviceIdentification id;
    id.readCode = readCode;
    id.conformity = 0x81; // basic category, stream and individual access
    const int first = readCode == 4 ? objectId : (objectId > 2 ? 0 : objectId);
    const int last = readCode == 4 ? objectId : 2;
    for (int object = first; object <= last; ++object)
        id.objects.insert(quint8(object), objects[object]);
    return QByteArray(1, char(ModbusRequest::EncapsulatedInterface)) + id.encode();
}

QString DcPidSimDevice::stateText() const
{
    static const char* const drives[] = {"idle", "running", "braking", "coasting", "locked"};
    return tr("%1 %2%3, output %4 %, command %5, line %6 %7")
        .arg(type(), QLatin1String(drives[int(m_drive)]),
             m_stallStopped ? tr(" (stall stop)") : QString(),
             QString::number(std::lround(m_motor.appliedDuty() * 100)), QString::number(m_command),
             QString::number(m_lineBaud), QString(QLatin1Char(m_lineParity)));
}

SimControlResult DcPidSimDevice::controlCommand(const QStringList& args, qint64 nowMs)
{
    const QString& cmd = args.first();
    const bool input = cmd == QLatin1String("input");
    if (input || cmd == QLatin1String("load")) {
        const qint64 min = input ? 0 : -100;
        const qint64 max = input ? 7 : 200;
        // Below the range when missing or not a number, so one test refuses all three.
        const qint64 v =
            (args.size() == 2 ? parseNumber(args.at(1)) : std::nullopt).value_or(min - 1);
        if (v < min || v > max)
            return fail(tr("usage: %1 ID VALUE with VALUE %2..%3 %4")
                            .arg(cmd)
                            .arg(min)
                            .arg(max)
                            .arg(input ? tr("(bit0 SQ1, bit1 SQ2, bit2 DE)") : tr("(% current)")));
        (input ? m_inputs : m_loadOffset) = int(v);
        return {true, tr("%1 = %2").arg(cmd).arg(v)};
    }
    if (cmd == QLatin1String("motor"))
        return motorCommand(args);
    return SimDevice::controlCommand(args, nowMs);
}

SimControlResult DcPidSimDevice::motorCommand(const QStringList& args)
{
    if (args.size() > 1) {
        QString why;
        const std::optional<DcMotor::Model> model =
            DcMotor::Model::parse(args.mid(1).join(QLatin1Char(',')), m_motor.model(), &why);
        if (!model)
            return fail(why);
        m_motor.setModel(*model);
    }
    return {true, tr("motor %1, speed %2 1/s, current %3 A")
                      .arg(m_motor.model().toString())
                      .arg(m_motor.commutation(), 0, 'f', 1)
                      .arg(m_motor.currentA(), 0, 'f', 2)};
}

} // namespace opentop
