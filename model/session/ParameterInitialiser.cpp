#include "model/session/ParameterInitialiser.h"

#include "model/profile/RoleEvaluator.h"
#include "model/profile/ValueCodec.h"
#include "model/session/DeviceSession.h"

#include <QHash>
#include <algorithm>
#include <memory>

namespace opentop {

namespace {

const QString kInit = QStringLiteral("parameterInit");
const QString kRunning = QStringLiteral("running");
const QString kCommunication = QStringLiteral("communication");
const QString kGroup = QStringLiteral("group");
const QString kIoPriority = QStringLiteral("ioPriority");

} // namespace

ParameterInitialiser::ParameterInitialiser(DeviceSession* session, QObject* parent)
    : QObject(parent)
    , m_session(session)
{
}

bool ParameterInitialiser::supported() const
{
    const ProfileRole* role = m_session->profile().role(kInit);
    const ParameterMeta* meta = RoleEvaluator::parameter(m_session->profile(), kInit);
    return role && role->value && meta && meta->isWritable();
}

QStringList ParameterInitialiser::readsNeeded() const
{
    const Profile& profile = m_session->profile();
    QStringList names;
    auto add = [&names](const ParameterMeta* meta) {
        if (meta && meta->isReadable() && !names.contains(meta->name))
            names << meta->name;
    };
    add(RoleEvaluator::parameter(profile, kRunning));
    add(RoleEvaluator::parameter(profile, kGroup));
    add(RoleEvaluator::parameter(profile, kIoPriority));
    if (const ProfileRole* role = profile.role(kCommunication)) {
        for (const QString& n : role->parameters)
            add(profile.parameter(n));
    }
    return names;
}

ParameterInitialiser::Plan
ParameterInitialiser::plan(const std::function<std::optional<double>(const QString&)>& raw,
                           const QStringList& unread) const
{
    Plan p;
    const Profile& profile = m_session->profile();
    const int slave = m_session->slave();
    const ValueContext context = m_session->context();
    const ParameterMeta* command = RoleEvaluator::parameter(profile, kInit);
    const ProfileRole* role = profile.role(kInit);
    if (!command || !role || !role->value) {
        p.refusal = tr("%1 drives have no parameter initialisation.").arg(profile.family);
        return p;
    }
    p.command = tr("%1 = %2 (register %3)")
                    .arg(command->label, RoleEvaluator::valueText(*command, *role->value, context),
                         command->addressText());

    // The motor must stand still.
    const ParameterMeta* runningMeta = RoleEvaluator::parameter(profile, kRunning);
    const std::optional<bool> running = RoleEvaluator::flag(profile, kRunning, raw);
    if (running.value_or(false))
        p.refusal = tr("Drive %1 is running. Stop the motor first: parameter initialisation is "
                       "only sent to a drive at standstill.")
                        .arg(slave);
    else if (runningMeta && !running)
        p.refusal = tr("Whether drive %1 is running could not be read (%2), so nothing was sent.")
                        .arg(slave)
                        .arg(unread.join(QStringLiteral(", ")));

    // What is reset: every group with settings.
    QStringList groups;
    for (const ProfileGroup& g : profile.groups) {
        for (const ParameterMeta* m : profile.parametersInGroup(g.id)) {
            if (m->kind == QLatin1String("setting") && m->isWritable()) {
                groups << g.label;
                break;
            }
        }
    }
    p.consequences << tr("Every setting of drive %1 returns to its factory default: %2. "
                         "Values set for this machine are lost; save a backup first to keep them.")
                          .arg(slave)
                          .arg(groups.join(QStringLiteral(", ")));

    // Settings that change how the drive is reached.
    auto change = [&](const ParameterMeta* meta, const QString& effect) {
        if (!meta)
            return;
        const ValueSpec& spec = meta->specFor(context);
        if (!spec.defaultRaw)
            return;
        const QString to = RoleEvaluator::valueText(*meta, qint64(*spec.defaultRaw), context);
        const std::optional<double> now = raw(meta->name);
        if (!now) {
            p.communication << meta->label;
            p.consequences
                << tr("%1 could not be read; it returns to %2. %3").arg(meta->label, to, effect);
        } else if (qint64(*now) != qint64(*spec.defaultRaw)) {
            p.communication << meta->label;
            p.consequences << tr("%1 goes from %2 back to %3. %4")
                                  .arg(meta->label,
                                       RoleEvaluator::valueText(*meta, qint64(*now), context), to,
                                       effect);
        } else {
            p.consequences << tr("%1 stays %2 (already the default).").arg(meta->label, to);
        }
    };
    const SerialDefaults& line = profile.serial;
    const QString lineText = tr("%1 bit/s, parity %2, %3 stop bit(s)")
                                 .arg(line.baud)
                                 .arg(QLatin1Char(line.parity))
                                 .arg(line.stopBits);
    if (const ProfileRole* comm = profile.role(kCommunication)) {
        for (const QString& n : comm->parameters) {
            const int before = p.communication.size();
            change(profile.parameter(n),
                   tr("The link to the drive is lost from its next power-up: it answers only at "
                      "the factory line settings, %1.")
                       .arg(lineText));
            if (p.communication.size() > before)
                p.reconnectBaud = line.baud;
        }
    }
    if (p.reconnectBaud > 0) {
        p.reconnectParity = line.parity;
        p.reconnectStopBits = line.stopBits;
        p.powerOnDelayMs = line.powerOnDelayMs;
        p.afterwards << tr("To reach drive %1 again: switch it off and on, wait %2 s after "
                           "power-on, then reconnect at %3.")
                            .arg(slave)
                            .arg(ValueCodec::formatNumber(std::max(line.powerOnDelayMs, 0) / 1000.0,
                                                          line.powerOnDelayMs % 1000 ? 1 : 0))
                            .arg(lineText);
    }
    change(RoleEvaluator::parameter(profile, kGroup),
           tr("The drive no longer follows writes sent to its group's parent, and drives that "
              "followed it no longer do."));
    const ParameterMeta* priority = RoleEvaluator::parameter(profile, kIoPriority);
    const ProfileRole* io = profile.role(kIoPriority);
    if (priority && io && io->value && priority->spec.defaultRaw &&
        qint64(*priority->spec.defaultRaw) == *io->value) {
        const std::optional<double> now = raw(priority->name);
        const bool lost = !now || qint64(*now) != *io->value;
        change(priority,
               tr("Bus control is lost: the drive follows its input terminals again and refuses "
                  "start, stop and speed commands over the bus; an input that is on may start the "
                  "motor, with the factory input functions."));
        if (lost) {
            p.busControlLost = true;
            const ParameterMeta* motion =
                RoleEvaluator::parameter(profile, QStringLiteral("motionPriority"));
            const ProfileRole* motionRole = profile.role(QStringLiteral("motionPriority"));
            if (motion && motionRole && motionRole->value)
                p.afterwards << tr("To control the motor over the bus again, set %1 to %2.")
                                    .arg(motion->label, RoleEvaluator::valueText(
                                                            *motion, *motionRole->value, context));
        }
    }
    p.consequences << tr("The machine number %1 is not a setting and does not change.").arg(slave);
    if (runningMeta && running == false)
        p.consequences << tr("The motor must stand still: drive %1 reports it stopped now, and "
                             "this is read again just before the command is sent.")
                              .arg(slave);
    return p;
}

void ParameterInitialiser::check(PlanDone done)
{
    const QStringList names = readsNeeded();
    QPointer<ParameterInitialiser> self(this);
    m_session->readMany(names, [self, done](const DeviceSession::ReadManyOutcome& o) {
        if (!self)
            return;
        QHash<QString, double> values;
        QStringList unread;
        for (const QString& n : o.order) {
            const DeviceSession::Outcome r = o.results.value(n);
            if (r.ok && r.value.valid)
                values.insert(n, r.value.raw);
            else
                unread << self->m_session->nameFor(n) + QStringLiteral(": ") + r.error;
        }
        done(self->plan(
            [&values](const QString& n) {
                return values.contains(n) ? std::optional<double>(values.value(n)) : std::nullopt;
            },
            unread));
    });
}

void ParameterInitialiser::run(Done done)
{
    QPointer<ParameterInitialiser> self(this);
    check([self, done](const Plan& plan) {
        if (!self)
            return;
        Outcome outcome;
        if (!plan.refusal.isEmpty()) {
            outcome.error = plan.refusal;
            done(outcome);
            return;
        }
        DeviceSession* session = self->m_session;
        const Profile& profile = session->profile();
        const ParameterMeta* command = RoleEvaluator::parameter(profile, kInit);
        const ProfileRole* role = profile.role(kInit);
        DeviceSession::WriteOptions options;
        options.explicitCommand = true; // the user confirmed exactly this, naming the drive
        session->write(command->name,
                       RoleEvaluator::writeText(*command, *role->value, session->context()),
                       options, [done](const DeviceSession::Outcome& o) {
                           Outcome out;
                           out.ok = o.ok;
                           out.sent = o.sent;
                           out.error = o.error;
                           done(out);
                       });
    });
}

} // namespace opentop
