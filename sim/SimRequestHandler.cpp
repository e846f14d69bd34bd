#include "sim/SimRequestHandler.h"

#include "model/profile/ValueCodec.h"
#include "sim/SimDevice.h"
#include "sim/SimLog.h"
#include "transport/ModbusCrc.h"
#include "transport/ModbusRequest.h"

namespace opentop {

namespace {

void appendWord(QByteArray* bytes, quint16 value)
{
    bytes->append(char(value >> 8));
    bytes->append(char(value & 0xFF));
}

} // namespace

SimRequestHandler::SimRequestHandler(SimDevice& device)
    : m_device(device)
{
}

QByteArray SimRequestHandler::handle(const ModbusRequest& request, qint64 nowMs,
                                     bool addressedDirectly)
{
    m_device.advance(nowMs);
    const bool reply = addressedDirectly && request.slave != 0;
    if (!reply && request.function != ModbusRequest::WriteSingle &&
        request.function != ModbusRequest::WriteMultiple)
        return {}; // broadcasts and group copies only execute writes
    m_device.frameSeen(nowMs);

    SimError error = SimError::None;
    QByteArray pdu;
    pdu.append(char(request.function));
    if (!m_device.supportsFunction(request.function)) {
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
        pdu = m_device.handleOther(request, nowMs, &error);
    }
    if (error != SimError::None) {
        qCDebug(lcSim) << "slave" << m_device.slave() << "refuses" << request.describe()
                       << int(error);
        m_device.recordError(error);
        return reply ? exceptionAdu(request.function, error) : QByteArray();
    }
    m_device.refreshStatus(nowMs);
    return reply ? adu(pdu) : QByteArray();
}

QByteArray SimRequestHandler::busyReply(const ModbusRequest& request, qint64 nowMs)
{
    m_device.advance(nowMs);
    m_device.frameSeen(nowMs);
    m_device.recordError(SimError::Busy);
    return exceptionAdu(request.function, SimError::Busy);
}

SimError SimRequestHandler::doRead(const ModbusRequest& request, QVector<quint16>* values) const
{
    if ((!request.rawData.isEmpty() && request.rawData.size() != 4) || request.count == 0 ||
        request.count > m_device.profile().maxReadRegisters)
        return SimError::BadFormat;
    if (int(request.address) + request.count > 0x10000)
        return SimError::IllegalAddress;
    for (int i = 0; i < request.count; ++i) {
        const quint16 a = quint16(request.address + i);
        if (!m_device.m_regs.readable(request.function, a) &&
            !m_device.m_regs.inReadBlock(request.function, a))
            return SimError::IllegalAddress;
        values->append(m_device.m_regs.readValue(request.function, a));
    }
    return SimError::None;
}

SimError SimRequestHandler::doWrite(const ModbusRequest& request, qint64 nowMs)
{
    const bool multiple = request.function == ModbusRequest::WriteMultiple;
    if (request.values.isEmpty() ||
        (!multiple && !request.rawData.isEmpty() && request.rawData.size() != 4))
        return SimError::BadFormat;
    if (multiple) {
        if (request.count == 0 || request.count > m_device.profile().maxWriteRegisters ||
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

    SimRegisters next = m_device.m_regs;
    QVector<const ParameterMeta*> touched;
    for (int i = 0; i < count; ++i) {
        const quint16 a = quint16(request.address + i);
        const ParameterMeta* p = m_device.m_regs.writable(a);
        if (!p) {
            const ParameterMeta* d = m_device.m_regs.declared(a);
            if (multiple &&
                ((d && d->kind == QLatin1String("reserved")) || m_device.acceptsGapWrite(a)))
                continue; // reserved registers inside a block write: ignored
            return m_device.m_regs.readable(3, a) ? SimError::ReadOnly : SimError::IllegalAddress;
        }
        const bool whole = p->address >= request.address &&
                           p->address + p->registerCount <= request.address + count;
        if (p->registerCount > 1 && !whole && !m_device.allowsPartialWrite(*p))
            return SimError::IllegalAddress;
        // A parameter the profile writes with 0x10 only takes 06 where parts may be written.
        if (!multiple && p->writeFunction == ModbusRequest::WriteMultiple &&
            !(p->registerCount > 1 && m_device.allowsPartialWrite(*p)))
            return SimError::IllegalAddress;
        next.setValue(SimRegisters::spaceOf(*p), a, request.values.at(i));
        if (!touched.contains(p) && p->kind != QLatin1String("reserved"))
            touched << p;
    }

    const ValueContext nextContext = m_device.contextOf(next);
    for (const ParameterMeta* p : touched) {
        const bool whole = p->address >= request.address &&
                           p->address + p->registerCount <= request.address + count;
        if (!whole)
            continue; // half of a 32-bit value: checked when the whole value is written
        const QString why = ValueCodec::checkRaw(*p, next.raw(*p), nextContext);
        if (!why.isEmpty()) {
            qCDebug(lcSim) << "slave" << m_device.slave() << p->name << why;
            return SimError::OutOfRange;
        }
    }
    for (const ParameterMeta* p : touched) {
        const SimError e = m_device.checkWrite(*p, next.raw(*p), nowMs);
        if (e != SimError::None)
            return e;
    }
    // A setting that does not stick (defect): acknowledged, but the old value stays.
    QVector<const ParameterMeta*> stuck;
    for (const ParameterMeta* p : touched) {
        if (m_device.m_defects.noStick.contains(p->name))
            next.setRegisters(*p, m_device.m_regs.registers(*p));
        else
            stuck << p;
    }
    m_device.m_regs = next;
    for (const ParameterMeta* p : stuck)
        m_device.afterWrite(*p, m_device.m_regs.raw(*p), nowMs);
    m_device.afterBlockWrite(request.function, request.address, count, nowMs);
    return SimError::None;
}

QByteArray SimRequestHandler::exceptionAdu(quint8 function, SimError error) const
{
    QByteArray pdu;
    pdu.append(char(function | 0x80));
    pdu.append(char(m_device.exceptionCode(error)));
    return adu(pdu);
}

QByteArray SimRequestHandler::adu(const QByteArray& pdu) const
{
    return ModbusCrc::append(QByteArray(1, char(m_device.slave())) + pdu);
}

} // namespace opentop
