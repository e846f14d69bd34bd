#include "model/run/RunControl.h"

#include "model/profile/ProfileRegistry.h"
#include "model/profile/RoleEvaluator.h"
#include "model/profile/ValueCodec.h"
#include "model/session/DeviceSession.h"
#include "transport/ModbusClient.h"

#include <QTimer>
#include <algorithm>

namespace opentop {

namespace {

const QString kPriority = QStringLiteral("motionPriority");
const QString kAlarmActive = QStringLiteral("alarmActive");

struct ActionInfo
{
    RunControl::Action action;
    const char* word;
    const char* role;
};

const ActionInfo kActions[] = {
    {RunControl::Action::Start, "start", "start"},
    {RunControl::Action::Stop, "stop", "stop"},
    {RunControl::Action::Cw, "cw", "cw"},
    {RunControl::Action::Ccw, "ccw", "ccw"},
    {RunControl::Action::Select, "select", "select"},
    {RunControl::Action::Hold, "hold", "hold"},
    {RunControl::Action::Free, "free", "free"},
    {RunControl::Action::Coast, "coast", "coast"},
    {RunControl::Action::Speed, "speed", "speedCommand"},
};

} // namespace

RunControl::RunControl(ModbusClient* client, const ProfileRegistry& registry, QObject* parent)
    : QObject(parent)
    , m_client(client)
    , m_registry(registry)
{
}

std::optional<RunControl::Command> RunControl::parse(const QStringList& words, QString* error)
{
    const QString word = words.value(0).toLower();
    for (const ActionInfo& a : kActions) {
        if (word != QLatin1String(a.word))
            continue;
        Command c;
        c.action = a.action;
        const bool takesValue = a.action == Action::Select || a.action == Action::Speed;
        if (words.size() != (takesValue ? 2 : 1)) {
            if (error)
                *error = takesValue
                             ? tr("%1 needs one value, e.g. \"%1 %2\"")
                                   .arg(word, a.action == Action::Select ? QStringLiteral("2")
                                                                         : QStringLiteral("50"))
                             : tr("%1 takes no value").arg(word);
            return std::nullopt;
        }
        if (a.action == Action::Select) {
            bool ok = false;
            c.select = words.at(1).toInt(&ok);
            if (!ok) {
                if (error)
                    *error = tr("select needs a running data number, e.g. \"select 2\"; got \"%1\"")
                                 .arg(words.at(1));
                return std::nullopt;
            }
        }
        if (a.action == Action::Speed)
            c.speed = words.at(1);
        return c;
    }
    if (error)
        *error = tr("unknown run command \"%1\"; use start, stop, cw, ccw, select N, hold, free, "
                    "coast or speed VALUE")
                     .arg(words.join(QLatin1Char(' ')));
    return std::nullopt;
}

QString RunControl::actionName(Action action)
{
    for (const ActionInfo& a : kActions) {
        if (a.action == action)
            return QLatin1String(a.word);
    }
    return QString();
}

QString RunControl::roleOf(Action action)
{
    for (const ActionInfo& a : kActions) {
        if (a.action == action)
            return QLatin1String(a.role);
    }
    return QString();
}

QStringList RunControl::actionsOf(const Profile& profile)
{
    QStringList names;
    for (const ActionInfo& a : kActions) {
        if (!RoleEvaluator::parameter(profile, QLatin1String(a.role)))
            continue;
        names << (a.action == Action::Select  ? QStringLiteral("select N")
                  : a.action == Action::Speed ? QStringLiteral("speed VALUE")
                                              : QLatin1String(a.word));
    }
    return names;
}

RunControl::Plan RunControl::plan(const DeviceSession& session, const Command& command)
{
    const Profile& profile = session.profile();
    const QString role = roleOf(command.action);
    const ProfileRole* r = profile.role(role);
    Plan p;
    p.meta = RoleEvaluator::parameter(profile, role);
    const bool needsValue = command.action != Action::Select && command.action != Action::Speed;
    if (!r || !p.meta || !p.meta->isWritable() || (needsValue && !r->value)) {
        p.failure = Failure::Unsupported;
        p.error = tr("%1 drives have no \"%2\" command; they take: %3")
                      .arg(profile.family, actionName(command.action),
                           actionsOf(profile).join(QStringLiteral(", ")));
        return p;
    }
    const ValueContext context = session.context();
    if (command.action == Action::Speed) {
        p.text = command.speed;
        p.description = RoleEvaluator::describeWrite(*p.meta, command.speed, context);
        return p;
    }
    qint64 raw = r->value.value_or(0);
    if (command.action == Action::Select) {
        // Running data N is code N-1 of the selection parameter.
        const QVector<EnumOption>& options = p.meta->specFor(context).options;
        raw = command.select - 1;
        const bool known = std::any_of(options.begin(), options.end(),
                                       [raw](const EnumOption& o) { return o.value == raw; });
        if (!known) {
            p.failure = Failure::InvalidValue;
            p.error = options.isEmpty()
                          ? tr("%1 has no selection codes").arg(context.nameFor(p.meta->name))
                          : tr("select %1: choose %2–%3 (%4 … %5)")
                                .arg(command.select)
                                .arg(options.first().value + 1)
                                .arg(options.last().value + 1)
                                .arg(options.first().label, options.last().label);
            return p;
        }
    }
    p.text = RoleEvaluator::writeText(*p.meta, raw, context);
    p.description = RoleEvaluator::describeWrite(
        *p.meta, RoleEvaluator::valueText(*p.meta, raw, context), context);
    return p;
}

void RunControl::execute(DeviceSession* session, const Command& command, Done done)
{
    const Plan p = plan(*session, command);
    Outcome o;
    o.plan = p;
    if (p.failure != Failure::None) {
        o.failure = p.failure;
        o.error = p.error;
        done(o);
        return;
    }
    const Profile& profile = session->profile();
    const ParameterMeta* priority = RoleEvaluator::parameter(profile, kPriority);
    if (!priority || !priority->isReadable() || p.meta->safety != QLatin1String("motion")) {
        sendCommand(session, p, done);
        return;
    }
    // Only a drive that takes motion commands over the bus gets one.
    session->read(priority->name, [this, session, p, o, priority,
                                   done](const DeviceSession::Outcome& r) mutable {
        const Profile& prof = session->profile();
        if (!r.value.valid) {
            o.failure = Failure::Communication;
            o.error = tr("cannot read %1 to check that the drive takes motion commands: %2")
                          .arg(priority->name, r.error);
            done(o);
            return;
        }
        const std::optional<bool> holds = RoleEvaluator::holds(
            prof, kPriority, [&r](const QString&) { return std::optional<double>(r.value.raw); });
        if (holds.value_or(true)) {
            sendCommand(session, p, done);
            return;
        }
        const qint64 wanted = prof.role(kPriority)->value.value_or(0);
        const ValueContext context = session->context();
        const QString current = ValueCodec::format(*priority, r.value, context);
        QString wantedLabel = RoleEvaluator::valueText(*priority, wanted, context);
        for (const EnumOption& e : priority->specFor(context).options) {
            if (e.value == wanted)
                wantedLabel = e.label;
        }
        o.failure = Failure::Priority;
        o.error = tr("machine number %1 is in \"%2\" (%3); nothing was sent")
                      .arg(session->slave())
                      .arg(current, priority->name);
        o.explanation =
            tr("In \"%1\" the drive takes run, stop, direction and speed selection from its input "
               "terminals and refuses motion commands over the bus. To test-run it from here, "
               "switch it to \"%2\": opentop-cli set %3 %4=%5 (and back to \"%1\", =%6, when "
               "the machine's own controls should run it again).")
                .arg(current, wantedLabel)
                .arg(session->slave())
                .arg(priority->name)
                .arg(wanted)
                .arg(qint64(r.value.raw));
        done(o);
    });
}

void RunControl::sendCommand(DeviceSession* session, const Plan& p, Done done)
{
    DeviceSession::WriteOptions explicitly;
    explicitly.explicitCommand = true;
    session->write(p.meta->name, p.text, explicitly,
                   [this, session, p, done](const DeviceSession::Outcome& w) {
                       Outcome o;
                       o.plan = p;
                       o.sent = w.sent;
                       o.ok = w.ok;
                       o.error = w.error;
                       o.deviceError = w.deviceError;
                       o.explanation = w.explanation; // what the device's code means
                       if (w.ok) {
                           done(o);
                       } else if (!w.sent) {
                           o.failure = Failure::InvalidValue;
                           done(o);
                       } else if (w.mismatch) {
                           o.failure = Failure::Mismatch; // written, read back differently
                           done(o);
                       } else {
                           o.failure = Failure::Communication;
                           explainRefusal(session, o, done);
                       }
                   });
}

void RunControl::explainRefusal(DeviceSession* session, Outcome o, Done done)
{
    const ParameterMeta* alarm = RoleEvaluator::parameter(session->profile(), kAlarmActive);
    if (o.deviceError.isEmpty() || !alarm || !alarm->isReadable()) {
        done(o);
        return;
    }
    session->read(alarm->name, [session, o, done](const DeviceSession::Outcome& r) mutable {
        const std::optional<bool> active =
            RoleEvaluator::flag(session->profile(), kAlarmActive, [&r](const QString&) {
                return r.value.valid ? std::optional<double>(r.value.raw) : std::nullopt;
            });
        if (active.value_or(false))
            o.explanation =
                tr("An alarm is active: the drive refuses to run until it is cleared. "
                   "See opentop-cli alarms %1, then alarms %1 --reset --yes.")
                    .arg(session->slave()) +
                (o.explanation.isEmpty() ? QString() : QLatin1Char('\n') + o.explanation);
        done(o);
    });
}

void RunControl::readState(DeviceSession* session, std::function<void(const State&)> done,
                           int settleMs)
{
    if (settleMs > 0) {
        QTimer::singleShot(settleMs, this, [this, session, done] { readState(session, done); });
        return;
    }
    const Profile& profile = session->profile();
    QStringList names;
    for (const char* role : {"running", "currentSpeed", "targetSpeed", "select"}) {
        const ParameterMeta* meta = RoleEvaluator::parameter(profile, QLatin1String(role));
        if (meta && meta->isReadable() && !names.contains(meta->name))
            names << meta->name;
    }
    session->readMany(names, [session, names, done](const DeviceSession::ReadManyOutcome& o) {
        const Profile& prof = session->profile();
        State state;
        state.ok = o.failed == 0;
        QStringList errors;
        for (const QString& name : names) {
            const DeviceSession::Outcome r = o.results.value(name);
            const ParameterMeta* meta = prof.parameter(name);
            if (!r.value.valid) {
                errors << QStringLiteral("%1: %2").arg(name, r.error);
                continue;
            }
            if (meta->type == DataType::Bits && !meta->bits.isEmpty()) {
                for (const BitField& f : meta->bits)
                    state.items.append(
                        {f.label,
                         RoleEvaluator::fieldText(f, RoleEvaluator::fieldValue(f, r.value.raw))});
            } else {
                state.items.append(
                    {meta->label, ValueCodec::format(*meta, r.value, session->context())});
            }
        }
        state.error = errors.join(QStringLiteral("; "));
        state.running = RoleEvaluator::flag(
            prof, QStringLiteral("running"), [&o](const QString& n) -> std::optional<double> {
                const auto r = o.results.value(n);
                return r.value.valid ? std::optional(r.value.raw) : std::nullopt;
            });
        done(state);
    });
}

QVector<RunControl::Broadcast> RunControl::broadcastPlan(const ProfileRegistry& registry)
{
    return StopAll::plan(registry);
}

void RunControl::stopAll(const QVector<int>& knownSlaves,
                         std::function<void(const StopReport&)> done)
{
    auto* stop = new StopAll(m_client, m_registry, this);
    stop->setSessionLookup(m_lookup);
    stop->setTiming(m_timing);
    stop->run(knownSlaves, [stop, done](const StopReport& report) {
        stop->deleteLater();
        done(report);
    });
}

} // namespace opentop
