#include "model/alarms/AlarmHistory.h"

#include "model/profile/RoleEvaluator.h"
#include "model/profile/ValueCodec.h"
#include "model/session/DeviceSession.h"

#include <memory>

namespace opentop {

namespace {

const QString kAlarm = QStringLiteral("alarm");
const QString kAlarmActive = QStringLiteral("alarmActive");
const QString kAlarmReset = QStringLiteral("alarmReset");

// Which record table each erase role empties.
const std::pair<const char*, const char*> kEraseRoles[] = {{"eraseAlarms", "alarm"},
                                                           {"eraseWarnings", "warning"}};

} // namespace

AlarmHistory::AlarmHistory(DeviceSession* session, QObject* parent)
    : QObject(parent)
    , m_session(session)
    , m_records(session)
{
}

bool AlarmHistory::supported() const
{
    return !m_records.recordParameters().isEmpty() || m_records.commErrorMeta();
}

bool AlarmHistory::canReset() const
{
    return !resetPlan().isEmpty();
}

bool AlarmHistory::canClear() const
{
    return !clearPlan().isEmpty();
}

QStringList AlarmHistory::resetPlan() const
{
    const Profile& profile = m_session->profile();
    const ProfileRole* role = profile.role(kAlarmReset);
    const ParameterMeta* meta = RoleEvaluator::parameter(profile, kAlarmReset);
    if (!role || !meta || !role->value)
        return {};
    const ValueContext context = m_session->context();
    return {RoleEvaluator::describeWrite(
        *meta, RoleEvaluator::valueText(*meta, *role->value, context), context)};
}

QStringList AlarmHistory::clearPlan() const
{
    const Profile& profile = m_session->profile();
    QStringList plan;
    for (const auto& [roleName, table] : kEraseRoles) {
        const QString name = QLatin1String(roleName);
        const ProfileRole* role = profile.role(name);
        const ParameterMeta* meta = RoleEvaluator::parameter(profile, name);
        if (!role || !meta || !role->value)
            continue;
        const CodeTable* codes = profile.codeTable(QLatin1String(table));
        plan << tr("%1: erases the %2")
                    .arg(RoleEvaluator::describeWrite(
                             *meta,
                             RoleEvaluator::valueText(*meta, *role->value, m_session->context()),
                             m_session->context()),
                         codes ? codes->label.toLower() : QLatin1String(table));
    }
    return plan;
}

void AlarmHistory::read(ReportDone done)
{
    const QStringList names = m_records.parametersToRead();
    m_session->readMany(names, [this, done](const DeviceSession::ReadManyOutcome& o) {
        QHash<QString, double> raw;
        QHash<QString, QString> errors;
        for (const QString& name : o.order) {
            const DeviceSession::Outcome r = o.results.value(name);
            if (r.value.valid) // decoded (perhaps outside the allowed set, still a reading)
                raw.insert(name, r.value.raw);
            else
                errors.insert(name, r.error);
        }
        Report report = m_records.decode(raw, errors);
        report.requests = o.requests;
        done(report);
    });
}

QString AlarmHistory::eraseMethodParameter() const
{
    return m_records.eraseMethodParameter();
}

void AlarmHistory::reset(ResetDone done)
{
    const Profile& profile = m_session->profile();
    if (!canReset()) {
        ResetOutcome o;
        o.explanation = tr("%1 drives have no alarm reset command").arg(profile.family);
        done(o);
        return;
    }
    // What is active and how the drive clears alarms, to explain the result afterwards.
    QStringList before;
    const ParameterMeta* active = RoleEvaluator::parameter(profile, kAlarmActive);
    if (active && active->isReadable())
        before << active->name;
    if (!profile.records(kAlarm).isEmpty())
        before << profile.records(kAlarm).first()->name;
    const ParameterMeta* method = profile.parameter(eraseMethodParameter());
    if (method && method->isReadable())
        before << method->name;
    m_session->readMany(before, [this, done](const DeviceSession::ReadManyOutcome& read) {
        sendReset(read, done);
    });
}

void AlarmHistory::sendReset(const DeviceSession::ReadManyOutcome& before, ResetDone done)
{
    const Profile& profile = m_session->profile();
    auto rawOf = [&before](const QString& n) -> std::optional<double> {
        const DeviceSession::Outcome r = before.results.value(n);
        return r.value.valid ? std::optional<double>(r.value.raw) : std::nullopt;
    };
    auto state = std::make_shared<ResetState>();
    state->outcome.wasActive = RoleEvaluator::flag(profile, kAlarmActive, rawOf).value_or(false);
    const QVector<const ParameterMeta*> records = profile.records(kAlarm);
    const CodeTable* codes = profile.codeTable(kAlarm);
    if (state->outcome.wasActive && !records.isEmpty() && codes) {
        const std::optional<double> code = rawOf(records.first()->name);
        if (const CodeEntry* e = code ? codes->find(qint64(*code)) : nullptr)
            state->outcome.alarm = *e;
    }
    if (const ParameterMeta* method = profile.parameter(eraseMethodParameter())) {
        const std::optional<double> raw = rawOf(method->name);
        state->powerMethod = raw && m_records.eraseMethodIsPower(*raw);
        state->methodText = QStringLiteral("%1 = %2").arg(
            method->name, ValueCodec::format(*method, before.results.value(method->name).value,
                                             m_session->context()));
    }
    const ProfileRole* role = profile.role(kAlarmReset);
    const ParameterMeta* meta = RoleEvaluator::parameter(profile, kAlarmReset);
    DeviceSession::WriteOptions explicitly;
    explicitly.explicitCommand = true;
    m_session->write(
        meta->name, RoleEvaluator::writeText(*meta, *role->value, m_session->context()), explicitly,
        [this, state, done](const DeviceSession::Outcome& w) {
            state->outcome.sent = w.sent;
            state->outcome.ok = w.ok;
            state->outcome.error = w.error;
            const ParameterMeta* active =
                RoleEvaluator::parameter(m_session->profile(), kAlarmActive);
            if (!active || !active->isReadable() || !w.sent) {
                finishReset(state, std::nullopt, done);
                return;
            }
            m_session->read(active->name, [this, state, done](const DeviceSession::Outcome& after) {
                const std::optional<bool> still = RoleEvaluator::flag(
                    m_session->profile(), kAlarmActive, [&after](const QString&) {
                        return after.value.valid ? std::optional<double>(after.value.raw)
                                                 : std::nullopt;
                    });
                finishReset(state, still, done);
            });
        });
}

void AlarmHistory::finishReset(const std::shared_ptr<ResetState>& state, std::optional<bool> still,
                               ResetDone done)
{
    ResetOutcome& o = state->outcome;
    o.stillActive = still;
    const QString name =
        o.alarm ? o.alarm->panel + QLatin1Char(' ') + o.alarm->name : tr("The alarm");
    if (still && !*still) {
        o.explanation = o.wasActive ? tr("%1 is cleared.").arg(name)
                                    : tr("No alarm was active; nothing to clear.");
    } else if (still && o.alarm && o.alarm->reset == QLatin1String("power")) {
        o.powerCycleNeeded = true;
        o.explanation = tr("%1 is still active: only a power cycle clears it. %2")
                            .arg(name, o.alarm->resetText);
    } else if (still && state->powerMethod) {
        o.powerCycleNeeded = true;
        o.explanation =
            tr("%1 is still active: the drive is set to clear alarms by a power restart "
               "only (%2). Remove the cause, turn the power off, wait 5 s and turn it "
               "on again; or change that setting to allow the reset command.")
                .arg(name, state->methodText);
    } else if (still) {
        o.explanation =
            tr("%1 is still active: its cause is still present%2. Remove the cause and "
               "turn off the start signal, then reset again.")
                .arg(name, o.alarm && !o.alarm->cause.isEmpty()
                               ? QStringLiteral(" (") + o.alarm->cause + QLatin1Char(')')
                               : QString());
    } else {
        o.explanation = o.ok ? tr("The reset was accepted; whether an alarm is still active could "
                                  "not be read.")
                             : tr("The reset failed: %1").arg(o.error);
    }
    if (!o.ok && o.sent && still.value_or(false))
        o.explanation += QLatin1Char(' ') + tr("(The drive refused the reset: %1)").arg(o.error);
    done(o);
}

void AlarmHistory::writeRoles(const QStringList& roles, std::function<void(QStringList)> done)
{
    auto errors = std::make_shared<QStringList>();
    auto queue = std::make_shared<QStringList>(roles);
    auto next = std::make_shared<std::function<void()>>();
    *next = [this, errors, queue, next, done] {
        if (queue->isEmpty()) {
            done(*errors);
            *next = nullptr; // break the cycle
            return;
        }
        const QString roleName = queue->takeFirst();
        const ProfileRole* role = m_session->profile().role(roleName);
        const ParameterMeta* meta = RoleEvaluator::parameter(m_session->profile(), roleName);
        DeviceSession::WriteOptions explicitly;
        explicitly.explicitCommand = true;
        m_session->write(meta->name,
                         RoleEvaluator::writeText(*meta, *role->value, m_session->context()),
                         explicitly, [errors, roleName, next](const DeviceSession::Outcome& o) {
                             if (!o.ok)
                                 errors->append(roleName + QLatin1Char('\t') + o.error);
                             (*next)();
                         });
    };
    (*next)();
}

void AlarmHistory::clearRecords(ClearDone done)
{
    QStringList roles;
    QStringList tables;
    for (const auto& [roleName, table] : kEraseRoles) {
        const ProfileRole* role = m_session->profile().role(QLatin1String(roleName));
        if (role && role->value &&
            RoleEvaluator::parameter(m_session->profile(), QLatin1String(roleName))) {
            roles << QLatin1String(roleName);
            tables << QLatin1String(table);
        }
    }
    read([this, roles, tables, done](const Report& before) {
        auto outcome = std::make_shared<ClearOutcome>();
        for (const History& h : before.histories)
            outcome->erasedRecords += tables.contains(h.table) ? h.used() : 0;
        writeRoles(roles, [this, roles, tables, outcome, done](const QStringList& errors) {
            for (int i = 0; i < roles.size(); ++i) {
                bool failed = false;
                for (const QString& e : errors) {
                    if (e.startsWith(roles[i] + QLatin1Char('\t'))) {
                        failed = true;
                        outcome->errors << e.section(QLatin1Char('\t'), 1);
                    }
                }
                if (!failed) {
                    const CodeTable* t = m_session->profile().codeTable(tables[i]);
                    outcome->cleared << (t ? t->label : tables[i]);
                }
            }
            read([outcome, tables, done](const Report& after) {
                bool empty = after.ok;
                for (const History& h : after.histories)
                    empty = empty && (!tables.contains(h.table) || h.used() == 0);
                outcome->verified = empty;
                outcome->ok = outcome->errors.isEmpty() && empty;
                done(*outcome);
            });
        });
    });
}

} // namespace opentop
