#include "sim/SimDevice.h"

#include "model/profile/ValueCodec.h"
#include "sim/SimBackdoor.h"
#include "sim/SimLog.h"
#include "sim/SimRequestHandler.h"
#include "transport/ModbusRequest.h"

#include <algorithm>

namespace opentop {

namespace {

constexpr qint64 kStepMs = 10;

} // namespace

SimDevice::SimDevice(const Profile& profile, const QString& variant, int slave)
    : m_profile(profile)
    , m_variant(variant)
    , m_slave(slave)
    , m_regs(&m_profile)
{
    // Two passes: a default may depend on another parameter's value (a "when" condition).
    for (int pass = 0; pass < 2; ++pass) {
        for (const ParameterMeta& p : m_profile.parameters)
            applyDefault(p);
    }
    for (const ParameterMeta& p : m_profile.parameters) {
        if (!p.storeWith.isEmpty())
            m_regs.storeParameter(p);
    }
}

SimDevice::~SimDevice() = default;

QByteArray SimDevice::handle(const ModbusRequest& request, qint64 nowMs, bool addressedDirectly)
{
    return SimRequestHandler(*this).handle(request, nowMs, addressedDirectly);
}

QByteArray SimDevice::busyReply(const ModbusRequest& request, qint64 nowMs)
{
    return SimRequestHandler(*this).busyReply(request, nowMs);
}

void SimDevice::applyDefault(const ParameterMeta& meta)
{
    const ValueSpec& spec = meta.specFor(context());
    if (meta.type == DataType::String) {
        m_regs.setText(meta, spec.defaultText, stringPad());
    } else if (spec.defaultRaw) {
        m_regs.setRaw(meta, *spec.defaultRaw);
    }
}

void SimDevice::afterWrite(const ParameterMeta& meta, double, qint64)
{
    if (m_regs.isStoreCommand(meta.name))
        m_regs.storeGroup(meta.name);
}

bool SimDevice::supportsFunction(quint8 function) const
{
    for (const ParameterMeta& p : m_profile.parameters) {
        if ((function == 3 || function == 4) && p.readFunction == function)
            return true;
        if ((function == 6 || function == 0x10) && p.isWritable())
            return true;
    }
    return false;
}

quint8 SimDevice::exceptionCode(SimError error) const
{
    switch (error) {
    case SimError::IllegalFunction:
        return 0x01;
    case SimError::IllegalAddress:
    case SimError::ReadOnly:
        return 0x02;
    case SimError::BadFormat:
    case SimError::OutOfRange:
        return 0x03;
    case SimError::Refused:
    case SimError::Prohibited:
        return 0x04;
    case SimError::Busy:
        return 0x06;
    case SimError::None:
        break;
    }
    return 0x04;
}

void SimDevice::recordError(SimError error)
{
    m_lastError = error;
}

QByteArray SimDevice::handleOther(const ModbusRequest&, qint64, SimError* error)
{
    *error = SimError::IllegalFunction;
    return {};
}

void SimDevice::advance(qint64 nowMs)
{
    if (m_lastAdvanceMs < 0 || nowMs < m_lastAdvanceMs) {
        m_lastAdvanceMs = nowMs;
    } else if (nowMs > m_lastAdvanceMs) {
        // Fixed 10 ms steps; coarser after long silences so that an idle hour stays cheap, and a
        // single step while the device is quiescent (the answer must not wait for the catch-up).
        const qint64 gap = nowMs - m_lastAdvanceMs;
        const qint64 stepMs = quiescent()
                                  ? std::max<qint64>(kStepMs, std::min<qint64>(gap, 3600000))
                                  : std::max<qint64>(kStepMs, gap / 20000);
        qint64 t = m_lastAdvanceMs;
        while (t < nowMs) {
            const qint64 dt = std::min(stepMs, nowMs - t);
            t += dt;
            step(t, int(dt));
        }
        m_lastAdvanceMs = nowMs;
    }
    refreshStatus(nowMs);
}

void SimDevice::powerCycle(qint64 nowMs)
{
    advance(nowMs);
    for (const ParameterMeta& p : m_profile.parameters) {
        if (!p.storeWith.isEmpty())
            m_regs.restoreParameter(p);
        else if (p.kind == QLatin1String("status") || p.kind == QLatin1String("command")) {
            if (p.isNumeric() || p.type == DataType::Bits)
                m_regs.setRaw(p, 0); // RAM: 0 unless the profile says otherwise
            applyDefault(p);
        }
    }
    for (auto it = m_powerOnValues.cbegin(); it != m_powerOnValues.cend(); ++it) {
        if (const ParameterMeta* p = param(it.key()))
            m_regs.setRegisters(*p, it.value()); // the setting never reached the EEPROM
    }
    m_lastError = SimError::None;
    onPowerCycle(nowMs);
    refreshStatus(nowMs);
    qCInfo(lcSim) << "slave" << m_slave << "power cycled";
}

void SimDevice::configureLine(int, char) {}

LineFormat SimDevice::lineFormat() const
{
    if (!lineBaud())
        return LineFormat();
    return LineFormat{lineBaud(), lineParity() ? lineParity() : 'N', 8, lineStopBits()};
}

QString SimDevice::stateText() const
{
    return type();
}

std::optional<double> SimDevice::raw(const QString& name) const
{
    const ParameterMeta* p = param(name);
    if (!p)
        return std::nullopt;
    return m_regs.raw(*p);
}

void SimDevice::setRaw(const QString& name, double raw)
{
    if (const ParameterMeta* p = param(name))
        m_regs.setRaw(*p, raw);
}

double SimDevice::rawOf(const QString& name) const
{
    return raw(name).value_or(0);
}

void SimDevice::setRawOf(const QString& name, double raw)
{
    setRaw(name, raw);
}

quint16 SimDevice::reg(quint8 function, quint16 address) const
{
    if (function == 6 || function == 0x10)
        return m_regs.value(SimRegisters::Space::Command, address);
    return m_regs.value(SimRegisters::spaceForFunction(function), address);
}

void SimDevice::setReg(quint8 function, quint16 address, quint16 value)
{
    if (function == 6 || function == 0x10)
        m_regs.setValue(SimRegisters::Space::Command, address, value);
    else
        m_regs.setValue(SimRegisters::spaceForFunction(function), address, value);
}

ValueContext SimDevice::context() const
{
    return contextOf(m_regs);
}

ValueContext SimDevice::contextOf(const SimRegisters& regs) const
{
    ValueContext c;
    c.variant = m_variant;
    c.parameterRaw = [this, &regs](const QString& name) -> std::optional<qint64> {
        const ParameterMeta* p = m_profile.parameter(name);
        if (!p)
            return std::nullopt;
        return qint64(regs.raw(*p));
    };
    return c;
}

std::optional<qint64> SimDevice::parseNumber(const QString& text)
{
    QString t = text.trimmed();
    bool negative = false;
    if (t.startsWith(QLatin1Char('-'))) {
        negative = true;
        t = t.mid(1);
    }
    bool ok = false;
    qint64 v = 0;
    if (t.startsWith(QLatin1String("0x"), Qt::CaseInsensitive))
        v = t.mid(2).toLongLong(&ok, 16);
    else if (t.endsWith(QLatin1Char('h'), Qt::CaseInsensitive))
        v = t.chopped(1).toLongLong(&ok, 16);
    else
        v = t.toLongLong(&ok, 10);
    if (!ok)
        return std::nullopt;
    return negative ? -v : v;
}

SimControlResult SimDevice::control(const QStringList& args, qint64 nowMs)
{
    advance(nowMs);
    if (args.isEmpty())
        return fail(tr("missing command"));
    const QString& cmd = args.first();
    SimControlResult result;
    if (cmd == QLatin1String("get") || cmd == QLatin1String("set")) {
        result = SimBackdoor(this).getSet(args);
    } else if (cmd == QLatin1String("defect")) {
        result = defectCommand(args);
    } else if (cmd == QLatin1String("power-cycle")) {
        powerCycle(nowMs);
        result.text = tr("slave %1 power cycled").arg(m_slave);
    } else {
        result = controlCommand(args, nowMs);
    }
    refreshStatus(nowMs);
    return result;
}

bool SimDevice::addDefects(const SimDefectSpec& spec, QString* error)
{
    const std::optional<SimDefects> next =
        SimDefects::resolve(m_defects.spec.merged(spec), m_profile, error);
    if (!next)
        return false;
    if (const ParameterMeta* version = param(m_profile.identify.versionParameter)) {
        if (next->firmware) {
            if (!m_trueFirmware)
                m_trueFirmware = quint16(m_regs.raw(*version));
            m_regs.setRaw(*version, *next->firmware);
        } else if (m_trueFirmware) {
            m_regs.setRaw(*version, *m_trueFirmware);
            m_trueFirmware.reset();
        }
    }
    for (const QString& name : m_powerOnValues.keys()) {
        if (!next->noStore.contains(name))
            m_powerOnValues.remove(name);
    }
    for (const QString& name : next->noStore) {
        const ParameterMeta* p = param(name);
        if (p && !m_powerOnValues.contains(name))
            m_powerOnValues.insert(name, p->storeWith.isEmpty() ? m_regs.registers(*p)
                                                                : m_regs.storedRegisters(*p));
    }
    m_defects = *next;
    qCInfo(lcSim) << "slave" << m_slave << "defects" << m_defects.spec.toString();
    return true;
}

SimControlResult SimDevice::defectCommand(const QStringList& args)
{
    if (args.size() < 2)
        return fail(tr("usage: defect ID DEFECT[,DEFECT...] or defect ID clear; DEFECT: %1")
                        .arg(SimDefectSpec::forms()));
    QString error;
    const std::optional<SimDefectSpec> spec =
        SimDefectSpec::parse(args.mid(1).join(QLatin1Char(',')), &error);
    if (!spec || !addDefects(*spec, &error))
        return fail(error);
    return {true, tr("slave %1 defects: %2")
                      .arg(m_slave)
                      .arg(m_defects.any() ? m_defects.spec.toString() : tr("none"))};
}

SimControlResult SimDevice::controlCommand(const QStringList& args, qint64)
{
    return fail(tr("'%1' is not supported by a %2 device").arg(args.first(), type()));
}

} // namespace opentop
