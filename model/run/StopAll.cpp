#include "model/run/StopAll.h"

#include "model/profile/ProfileRegistry.h"
#include "model/profile/RoleEvaluator.h"
#include "model/profile/ValueCodec.h"
#include "model/session/DeviceIdentifier.h"
#include "model/session/DeviceSession.h"
#include "transport/ModbusClient.h"

#include <algorithm>

namespace opentop {

struct StopAll::Run
{
    QVector<int> slaves;
    int next = 0;
    int broadcastIndex = 0;
    int confirming = 0;
    bool identified = false;
    bool finished = false;
    QElapsedTimer sinceStop;
    StopReport report;
    Done done;
    DeviceIdentifier* identifier = nullptr; // child of the RunControl, deleted when done
};

bool StopReport::broadcastOk() const
{
    return std::all_of(broadcasts.begin(), broadcasts.end(),
                       [](const StopBroadcast& b) { return b.sent; });
}

bool StopReport::allStopped() const
{
    return std::all_of(drives.begin(), drives.end(),
                       [](const StopResult& r) { return r.state == StopResult::State::Stopped; });
}

bool StopReport::anyStillRunning() const
{
    return std::any_of(drives.begin(), drives.end(), [](const StopResult& r) {
        return r.state == StopResult::State::StillRunning;
    });
}

bool StopReport::anyNoAnswer() const
{
    return std::any_of(drives.begin(), drives.end(),
                       [](const StopResult& r) { return r.state == StopResult::State::NoAnswer; });
}

StopAll::StopAll(ModbusClient* client, const ProfileRegistry& registry, QObject* parent)
    : QObject(parent)
    , m_client(client)
    , m_registry(registry)
{
}

QVector<StopBroadcast> StopAll::plan(const ProfileRegistry& registry)
{
    QVector<StopBroadcast> plan;
    for (const Profile& profile : registry.profiles()) {
        const ProfileRole* role = profile.role(QStringLiteral("stop"));
        const ParameterMeta* meta = RoleEvaluator::parameter(profile, QStringLiteral("stop"));
        if (!profile.supportsBroadcast || !role || !role->value || !meta || !meta->isWritable())
            continue;
        StopBroadcast b;
        b.family = profile.family;
        b.meta = meta;
        b.raw = *role->value;
        b.description =
            RoleEvaluator::describeWrite(*meta, RoleEvaluator::valueText(*meta, b.raw, {}));
        plan << b;
    }
    return plan;
}

void StopAll::run(const QVector<int>& knownSlaves, Done done)
{
    auto state = std::make_shared<Run>();
    state->slaves = knownSlaves;
    state->done = std::move(done);
    state->report.broadcasts = plan(m_registry);
    state->sinceStop.start();
    broadcastNext(state);
}

void StopAll::broadcastNext(std::shared_ptr<Run> state)
{
    if (state->broadcastIndex >= state->report.broadcasts.size()) {
        // Every family has been told to stop; now see that each known drive did.
        state->identifier = new DeviceIdentifier(m_client, m_registry, this);
        confirmNext(state);
        return;
    }
    const StopBroadcast& b = state->report.broadcasts[state->broadcastIndex];
    const QVector<quint16> regs = ValueCodec::rawToRegisters(*b.meta, double(b.raw));
    ModbusRequest request = b.meta->writeFunction == 16
                                ? ModbusRequest::writeMultiple(0, b.meta->address, regs)
                                : ModbusRequest::writeSingle(0, b.meta->address, regs.value(0));
    request.priority = ModbusRequest::Priority::User;
    m_client->submit(request, this, [this, state](const ModbusResult& r) {
        StopBroadcast& sent = state->report.broadcasts[state->broadcastIndex++];
        sent.sent = r.ok();
        sent.error = r.ok() ? QString() : r.errorText();
        broadcastNext(state);
    });
}

void StopAll::confirmNext(std::shared_ptr<Run> state)
{
    if (state->next >= state->slaves.size()) {
        state->identified = true;
        finishIfDone(state);
        return;
    }
    const int slave = state->slaves[state->next++];
    const int index = state->report.drives.size();
    StopResult pending;
    pending.slave = slave;
    state->report.drives << pending;
    if (DeviceSession* session = m_lookup ? m_lookup(slave) : nullptr) {
        confirm(state, index, session);
        confirmNext(state);
        return;
    }
    state->identifier->identify(slave, [this, state, index, slave](const DeviceInfo& info) {
        const Profile* profile = m_registry.family(info.family);
        if (info.state == DeviceInfo::State::Present && profile) {
            confirm(state, index, new DeviceSession(m_client, *profile, slave, info.variant, this));
        } else {
            StopResult& r = state->report.drives[index];
            r.state = StopResult::State::NoAnswer;
            r.elapsedMs = state->sinceStop.elapsed();
            // The state column already says "no answer"; the detail says why.
            r.detail =
                info.state == DeviceInfo::State::Absent && !info.detail.isEmpty()
                    ? info.detail
                    : DeviceInfo::stateText(info.state) +
                          (info.detail.isEmpty() ? QString() : QStringLiteral(": ") + info.detail);
        }
        confirmNext(state);
    });
}

void StopAll::confirm(std::shared_ptr<Run> state, int index, DeviceSession* session)
{
    ++state->confirming;
    auto* confirmer = new StopConfirmer(session, state->sinceStop, m_timing, this);
    confirmer->start([this, state, index, confirmer](const StopResult& result) {
        state->report.drives[index] = result;
        --state->confirming;
        confirmer->deleteLater();
        finishIfDone(state);
    });
}

void StopAll::finishIfDone(const std::shared_ptr<Run>& state)
{
    if (state->finished || !state->identified || state->confirming > 0)
        return;
    state->finished = true;
    if (state->identifier)
        state->identifier->deleteLater();
    state->done(state->report);
}

} // namespace opentop
