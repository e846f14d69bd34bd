#include "model/run/GroupFollowers.h"

#include "model/bus/DriveName.h"
#include "model/profile/RoleEvaluator.h"
#include "model/profile/ValueCodec.h"
#include "model/session/DeviceRefusal.h"
#include "model/session/DeviceSession.h"

#include <memory>

namespace opentop {

namespace {

const QString kPriority = QStringLiteral("motionPriority");
const QString kAlarm = QStringLiteral("alarmActive");
const QString kRunning = QStringLiteral("running");
const QString kSpeed = QStringLiteral("currentSpeed");

QStringList namesToRead(const Profile& profile, bool after)
{
    QStringList names;
    QStringList roles{kPriority, kAlarm};
    if (after)
        roles << kRunning << kSpeed;
    for (const QString& role : roles) {
        const ParameterMeta* meta = RoleEvaluator::parameter(profile, role);
        if (meta && meta->isReadable() && !names.contains(meta->name))
            names << meta->name;
    }
    if (after)
        if (const ParameterMeta* reg = DeviceRefusal::errorRegister(profile))
            names << reg->name;
    return names;
}

} // namespace

void GroupFollowers::readBefore(const QVector<DeviceSession*>& children, Done done)
{
    read(children, false, std::move(done));
}

void GroupFollowers::readAfter(const QVector<DeviceSession*>& children, Done done)
{
    read(children, true, std::move(done));
}

void GroupFollowers::read(const QVector<DeviceSession*>& children, bool after, Done done)
{
    struct State
    {
        QVector<Drive> drives;
        int pending = 1;
        Done done;
    };
    auto state = std::make_shared<State>();
    state->done = std::move(done);
    auto finish = [state] {
        if (--state->pending == 0)
            state->done(state->drives);
    };
    for (DeviceSession* child : children) {
        const int index = int(state->drives.size());
        Drive d;
        d.slave = child->slave();
        d.name = child->machineName();
        state->drives << d;
        ++state->pending;
        QPointer<DeviceSession> session(child);
        child->readMany(
            namesToRead(child->profile(), after),
            [state, index, session, after, finish](const DeviceSession::ReadManyOutcome& o) {
                if (session) {
                    Drive& out = state->drives[index];
                    out = decode(*session, after);
                    if (o.failed > 0 && out.why.isEmpty())
                        out.why = tr("could not be read");
                }
                finish();
            });
    }
    finish();
}

GroupFollowers::Drive GroupFollowers::decode(DeviceSession& session, bool after)
{
    const Profile& profile = session.profile();
    const ValueContext context = session.context();
    Drive d;
    d.slave = session.slave();
    d.name = session.machineName();
    auto raw = [&session](const QString& name) -> std::optional<double> {
        const ParamValue v = session.cachedValue(name);
        return v.valid ? std::optional<double>(v.raw) : std::nullopt;
    };
    // Only what was just read counts: readMany updated the cache before this runs.
    const ParameterMeta* priority = RoleEvaluator::parameter(profile, kPriority);
    const std::optional<bool> communication = RoleEvaluator::holds(profile, kPriority, raw);
    if (priority && session.cachedValue(priority->name).valid)
        d.priority = ValueCodec::format(*priority, session.cachedValue(priority->name), context);
    d.alarm = RoleEvaluator::flag(profile, kAlarm, raw).value_or(false);
    if (!priority) {
        d.follows = !d.alarm; // a family without a priority setting takes them always
    } else if (communication) {
        d.follows = *communication && !d.alarm;
    }
    if (!d.follows)
        d.why = tr("its control priority could not be read");
    else if (communication && !*communication)
        d.why = tr("it is in %1: it takes run commands only from its input terminals and "
                   "ignores them over the bus")
                    .arg(d.priority);
    else if (d.alarm)
        d.why = tr("an alarm is active: it runs only once the alarm is cleared");
    if (!after)
        return d;
    d.running = RoleEvaluator::flag(profile, kRunning, raw);
    if (const ParameterMeta* speed = RoleEvaluator::parameter(profile, kSpeed);
        speed && session.cachedValue(speed->name).valid)
        d.speed = ValueCodec::format(*speed, session.cachedValue(speed->name), context);
    const ParameterMeta* reg = DeviceRefusal::errorRegister(profile);
    const ParamValue code = reg ? session.cachedValue(reg->name) : ParamValue();
    if (code.valid && qint64(code.raw) != 0) {
        const CodeTable* table = profile.codeTable(reg->codeTable);
        const CodeEntry* entry = table ? table->find(qint64(code.raw)) : nullptr;
        d.commError =
            entry ? entry->explained()
                  : tr("error code %1h").arg(QString::number(qint64(code.raw), 16).toUpper());
    }
    return d;
}

QVector<int> GroupFollowers::notFollowing(const QVector<Drive>& drives)
{
    QVector<int> out;
    for (const Drive& d : drives)
        if (!d.follows.value_or(false))
            out << d.slave;
    return out;
}

QString GroupFollowers::listed(const Drive& d)
{
    return DriveName::listed(d.slave, d.name);
}

QStringList GroupFollowers::beforeLines(const QVector<Drive>& drives)
{
    QStringList lines;
    for (const Drive& d : drives) {
        if (d.follows.value_or(false))
            lines << (d.priority.isEmpty()
                          ? tr("Machine number %1 follows it.").arg(listed(d))
                          : tr("Machine number %1 follows it (%2).").arg(listed(d), d.priority));
        else if (!d.follows)
            lines
                << tr("Machine number %1: not known whether it follows: %2.").arg(listed(d), d.why);
        else
            lines << tr("Machine number %1 does NOT follow it: %2. To run it with this drive, "
                        "set its control priority to communication priority; otherwise it "
                        "shows E2h \"Cannot execute command\".")
                         .arg(listed(d), d.why);
    }
    return lines;
}

QStringList GroupFollowers::afterLines(const QVector<Drive>& drives)
{
    QStringList lines;
    for (const Drive& d : drives) {
        QString line;
        if (!d.running)
            line = tr("Machine number %1: its run state could not be read.").arg(listed(d));
        else if (*d.running)
            line = d.speed.isEmpty() ? tr("Machine number %1 runs.").arg(listed(d))
                                     : tr("Machine number %1 runs (%2).").arg(listed(d), d.speed);
        else if (!d.why.isEmpty())
            line = tr("Machine number %1 does not run: %2.").arg(listed(d), d.why);
        else
            line = tr("Machine number %1 does not run.").arg(listed(d));
        if (d.running && !*d.running && !d.commError.isEmpty())
            line += QLatin1Char(' ') + tr("It shows %1").arg(d.commError);
        lines << line;
    }
    return lines;
}

} // namespace opentop
