#include "model/session/BlockReader.h"

#include "model/profile/ValueCodec.h"
#include "model/session/ReadPlanner.h"
#include "transport/ModbusClient.h"

#include <utility>

namespace opentop {

namespace {

// Blocks of one readMany queued on the bus at a time: the next is waiting when one completes,
// so the worker goes on at once instead of waiting for this thread to hand it over. Two keep
// that true and leave room for user requests to overtake.
constexpr int kBlocksInFlight = 2;

} // namespace

struct BlockReader::State
{
    QVector<ReadBlockPlan> queue;
    int inFlight = 0;
    bool finished = false;
    DeviceSession::ReadManyOutcome outcome;
    DeviceSession::ManyDone done;
    ModbusRequest::Priority priority = ModbusRequest::Priority::Normal;
};

ModbusRequest BlockReader::requestFor(int slave, const ParameterMeta& meta)
{
    return meta.readFunction == 4
               ? ModbusRequest::readInput(quint8(slave), meta.address, quint16(meta.registerCount))
               : ModbusRequest::readHolding(quint8(slave), meta.address,
                                            quint16(meta.registerCount));
}

void BlockReader::read(DeviceSession* session, const QStringList& names,
                       DeviceSession::ManyDone done, ModbusRequest::Priority priority)
{
    auto state = std::make_shared<State>();
    state->priority = priority;
    state->done = std::move(done);
    state->outcome.order = names;
    QVector<const ParameterMeta*> metas;
    for (const QString& name : names) {
        DeviceSession::Outcome o;
        const ParameterMeta* meta = session->lookup(name, &o);
        if (meta && !meta->isReadable())
            o.error = DeviceSession::tr("%1 cannot be read (it is a write-only command)").arg(name);
        if (!o.error.isEmpty()) {
            state->outcome.results.insert(name, o);
            ++state->outcome.failed;
            continue;
        }
        metas << meta;
    }
    state->queue = ReadPlanner::plan(session->profile(), metas);
    next(session, state);
}

void BlockReader::next(DeviceSession* session, std::shared_ptr<State> state)
{
    if (state->queue.isEmpty() && state->inFlight == 0) {
        if (!std::exchange(state->finished, true))
            state->done(state->outcome);
        return;
    }
    while (state->inFlight < kBlocksInFlight && !state->queue.isEmpty())
        submit(session, state, state->queue.takeFirst());
}

void BlockReader::submit(DeviceSession* session, std::shared_ptr<State> state,
                         const ReadBlockPlan& plan)
{
    const quint8 slave = quint8(session->slave());
    ModbusRequest request = plan.function == 4
                                ? ModbusRequest::readInput(slave, plan.address, plan.count)
                                : ModbusRequest::readHolding(slave, plan.address, plan.count);
    request.priority = state->priority;
    ++state->outcome.requests;
    ++state->inFlight;
    session->client()->submit(request, session, [session, plan, state](const ModbusResult& r) {
        --state->inFlight;
        if (!r.ok() && r.error == ModbusError::Exception && plan.parameters.size() > 1) {
            // The device refuses the block: ask for each parameter on its own.
            const QVector<ReadBlockPlan> singles = ReadPlanner::singles(plan.parameters);
            for (int i = singles.size() - 1; i >= 0; --i)
                state->queue.prepend(singles[i]);
            next(session, state);
            return;
        }
        for (const ParameterMeta* meta : plan.parameters) {
            DeviceSession::Outcome o;
            o.parameter = meta->name;
            o.sent = true;
            if (!r.ok()) {
                o.error = r.errorText();
                ++state->outcome.failed;
            } else {
                const QVector<quint16> regs =
                    r.registers.mid(meta->address - plan.address, meta->registerCount);
                session->acceptRegisters(meta->name, regs);
                o.value = ValueCodec::decode(*meta, regs, session->context());
                o.ok = o.value.valid;
                o.error = o.value.error;
            }
            state->outcome.results.insert(meta->name, o);
        }
        next(session, state);
    });
}

} // namespace opentop
