#include "model/session/BlockWriter.h"

#include "model/session/DeviceSession.h"
#include "transport/ModbusClient.h"

namespace opentop {

void BlockWriter::frame(DeviceSession* session, const ParameterMeta& meta,
                        const QVector<quint16>& registers,
                        std::function<void(const ModbusRequest&, const QString&)> then)
{
    const quint8 slave = quint8(session->slave());
    const BlockWrite& block = meta.writeBlock;
    if (!block.isSet()) {
        then(meta.writeFunction == 16
                 ? ModbusRequest::writeMultiple(slave, meta.address, registers)
                 : ModbusRequest::writeSingle(slave, meta.address, registers.first()),
             QString());
        return;
    }
    const ParameterMeta* m = &meta;
    session->client()->submit(
        ModbusRequest::readHolding(slave, block.address, quint16(block.readCount())), session,
        [session, m, registers, slave, then](const ModbusResult& r) {
            const BlockWrite& b = m->writeBlock;
            if (!r.ok() || r.registers.size() != b.readCount()) {
                then(ModbusRequest(),
                     DeviceSession::tr("not written: %1 is written together with 0x%2–0x%3, and "
                                       "reading those first failed: %4")
                         .arg(session->nameFor(m->name))
                         .arg(b.address, 4, 16, QLatin1Char('0'))
                         .arg(b.address + b.count - 1, 4, 16, QLatin1Char('0'))
                         .arg(r.ok() ? DeviceSession::tr("short reply") : r.errorText()));
                return;
            }
            QVector<quint16> frame = r.registers;
            const int at = m->address - b.address;
            for (int i = 0; i < registers.size(); ++i)
                frame[at + i] = registers.at(i);
            frame += b.tail;
            then(ModbusRequest::writeMultiple(slave, b.address, frame), QString());
        });
}

} // namespace opentop
