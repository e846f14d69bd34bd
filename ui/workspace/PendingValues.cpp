#include "ui/workspace/PendingValues.h"

#include "model/profile/ValueCodec.h"
#include "model/session/DeviceParameters.h"
#include "model/session/DeviceSession.h"

namespace opentop {

QVector<quint16> PendingValues::registers(const DeviceParameters* parameters, const QString& name)
{
    const DeviceParameters::Entry* e = parameters->entry(name);
    if (!e)
        return {};
    // A failed write keeps its edit: it is still what the user wants written.
    const bool pending = e->state == DeviceParameters::State::Pending ||
                         e->state == DeviceParameters::State::Writing ||
                         (e->state == DeviceParameters::State::Failed && !e->pendingText.isEmpty());
    if (pending && !e->pendingRegisters.isEmpty())
        return e->pendingRegisters;
    return e->device.valid ? e->device.registers : QVector<quint16>();
}

std::optional<double> PendingValues::number(const DeviceParameters* parameters, const QString& name)
{
    const QVector<quint16> regs = registers(parameters, name);
    const DeviceParameters::Entry* e = parameters->entry(name);
    if (regs.isEmpty() || !e)
        return std::nullopt;
    const ParamValue v = ValueCodec::decode(*e->meta, regs, context(parameters));
    if (!v.valid)
        return std::nullopt;
    return v.number;
}

ValueContext PendingValues::context(const DeviceParameters* parameters)
{
    ValueContext c = parameters->session()->context();
    const auto base = c.parameterRaw;
    c.parameterRaw = [parameters, base](const QString& name) -> std::optional<qint64> {
        const DeviceParameters::Entry* e = parameters->entry(name);
        if (e && !e->pendingRegisters.isEmpty() && e->state != DeviceParameters::State::Clean)
            return qint64(ValueCodec::registersToRaw(*e->meta, e->pendingRegisters));
        return base ? base(name) : std::nullopt;
    };
    return c;
}

} // namespace opentop
