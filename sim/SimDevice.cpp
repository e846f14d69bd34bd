#include "SimDevice.h"

#include "ModbusCrc.h"
#include "ModbusRequest.h"
#include "SimBackdoor.h"
#include "SimLog.h"
#include "profile/ValueCodec.h"

#include <algorithm>

namespace opentop {

namespace {

constexpr qint64 kStepMs = 10;

void appendWord(QByteArray* bytes, quint16 value)
{
    bytes->append(char(value >> 8));
    bytes->append(char(value & 0xFF));
}

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

void SimDevice::applyDefault(const ParameterMeta& meta)
{
    const ValueSpec& spec = meta.specFor(context());
    if (meta.type == DataType::String) {
        m_regs.setText(meta, spec.defaultText, stringPad());
    } else if (spec.defaultRaw) {
        m_regs.setRaw(meta, *spec.defaultRaw);
    }
}

QByteArray SimDevice::handle(const ModbusRequest& request, qint64 nowMs, bool addressedDirectly)
{
    advance(nowMs);
    const bool reply = addressedDirectly && request.slave != 0;
    if (!reply && request.function != ModbusRequest::WriteSingle &&
        request.function != ModbusRequest::WriteMultiple)
        return {}; // broadcasts and group copies only execute writes
    frameSeen(nowMs);

    SimError error = SimError::None;
    QByteArray pdu;
    pdu.append(char(request.function));
    if (!supportsFunction(request.function)) {
        error = SimError::IllegalFunction;
    } else if (request.function == ModbusRequest::ReadHolding ||
               request.function == ModbusRequest::ReadInput) {
        QVector<quint16> values;
        error = doRead(request, &values);
        pdu.append(char(values.size() * 2));
        for (quint16 v : values)
            appendWord(&pdu, v);
    } else if (request.function == ModbusRequest::WriteSingle ||
               request.function == ModbusRequest::WriteMultiple) {
        error = doWrite(request, nowMs);
        appendWord(&pdu, request.address);
        appendWord(&pdu, request.function == ModbusRequest::WriteSingle
                             ? (request.values.isEmpty() ? 0 : request.values.first())
                             : request.count);
    } else {
        pdu = handleOther(request, nowMs, &error);
    }
    if (error != SimError::None) {
        qCDebug(lcSim) << "slave" << m_slave << "refuses" << request.describe() << int(error);
        recordError(error);
        return reply ? exceptionAdu(request.function, error) : QByteArray();
    }
    refreshStatus(nowMs);
    return reply ? adu(pdu) : QByteArray();
}

QByteArray SimDevice::busyReply(const ModbusRequest& request, qint64 nowMs)
{
    advance(nowMs);
    frameSeen(nowMs);
    recordError(SimError::Busy);
    return exceptionAdu(request.function, SimError::Busy);
}

SimError SimDevice::doRead(const ModbusRequest& request, QVector<quint16>* values) const
{
    if ((!request.rawData.isEmpty() && request.rawData.size() != 4) || request.count == 0 ||
        request.count > m_profile.maxReadRegisters)
        return SimError::BadFormat;
    if (int(request.address) + request.count > 0x10000)
        return SimError::IllegalAddress;
    for (int i = 0; i < request.count; ++i) {
        const quint16 a = quint16(request.address + i);
        if (!m_regs.readable(request.function, a) && !m_regs.inReadBlock(request.function, a))
            return SimError::IllegalAddress;
        values->append(m_regs.readValue(request.function, a));
    }
    return SimError::None;
}

SimError SimDevice::doWrite(const ModbusRequest& request, qint64 nowMs)
{
    const bool multiple = request.function == ModbusRequest::WriteMultiple;
    if (request.values.isEmpty() ||
        (!multiple && !request.rawData.isEmpty() && request.rawData.size() != 4))
        return SimError::BadFormat;
    if (multiple) {
        if (request.count == 0 || request.count > m_profile.maxWriteRegisters ||
            request.values.size() != request.count)
            return SimError::BadFormat;
        // rawData: address(2) count(2) byte count(1) data; the byte count must match.
        if (!request.rawData.isEmpty() &&
            (request.rawData.size() < 5 || quint8(request.rawData.at(4)) != request.count * 2 ||
             request.rawData.size() != 5 + request.count * 2))
            return SimError::BadFormat;
    }
    const int count = multiple ? request.count : 1;
    if (int(request.address) + count > 0x10000)
        return SimError::IllegalAddress;

    SimRegisters next = m_regs;
    QVector<const ParameterMeta*> touched;
    for (int i = 0; i < count; ++i) {
        const quint16 a = quint16(request.address + i);
        const ParameterMeta* p = m_regs.writable(a);
        if (!p) {
            const ParameterMeta* d = m_regs.declared(a);
            if (multiple && ((d && d->kind == QLatin1String("reserved")) || acceptsGapWrite(a)))
                continue; // reserved registers inside a block write: ignored
            return m_regs.readable(3, a) ? SimError::ReadOnly : SimError::IllegalAddress;
        }
        const bool whole = p->address >= request.address &&
                           p->address + p->registerCount <= request.address + count;
        if (p->registerCount > 1 && !whole && !allowsPartialWrite(*p))
            return SimError::IllegalAddress;
        // A parameter the profile writes with 0x10 only takes 06 where parts may be written.
        if (!multiple && p->writeFunction == ModbusRequest::WriteMultiple &&
            !(p->registerCount > 1 && allowsPartialWrite(*p)))
            return SimError::IllegalAddress;
        next.setValue(SimRegisters::spaceOf(*p), a, request.values.at(i));
        if (!touched.contains(p) && p->kind != QLatin1String("reserved"))
            touched << p;
    }

    const ValueContext nextContext = contextOf(next);
    for (const ParameterMeta* p : touched) {
        const bool whole = p->address >= request.address &&
                           p->address + p->registerCount <= request.address + count;
        if (!whole)
            continue; // half of a 32-bit value: checked when the whole value is written
        const QString why = ValueCodec::checkRaw(*p, next.raw(*p), nextContext);
        if (!why.isEmpty()) {
            qCDebug(lcSim) << "slave" << m_slave << p->name << why;
            return SimError::OutOfRange;
        }
    }
    for (const ParameterMeta* p : touched) {
        const SimError e = checkWrite(*p, next.raw(*p), nowMs);
        if (e != SimError::None)
            return e;
    }
    m_regs = next;
    for (const ParameterMeta* p : touched)
        afterWrite(*p, m_regs.raw(*p), nowMs);
    afterBlockWrite(request.function, request.address, count, nowMs);
    return SimError::None;
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

QByteArray SimDevice::exceptionAdu(quint8 function, SimError error) const
{
    QByteArray pdu;
    pdu.append(char(function | 0x80));
    pdu.append(char(exceptionCode(error)));
    return adu(pdu);
}

QByteArray SimDevice::adu(const QByteArray& pdu) const
{
    return ModbusCrc::append(QByteArray(1, char(m_slave)) + pdu);
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
    m_lastError = SimError::None;
    onPowerCycle(nowMs);
    refreshStatus(nowMs);
    qCInfo(lcSim) << "slave" << m_slave << "power cycled";
}

void SimDevice::configureLine(int, char) {}

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
    } else if (cmd == QLatin1String("power-cycle")) {
        powerCycle(nowMs);
        result.text = tr("slave %1 power cycled").arg(m_slave);
    } else {
        result = controlCommand(args, nowMs);
    }
    refreshStatus(nowMs);
    return result;
}

SimControlResult SimDevice::controlCommand(const QStringList& args, qint64)
{
    return fail(tr("'%1' is not supported by a %2 device").arg(args.first(), type()));
}

} // namespace opentop
