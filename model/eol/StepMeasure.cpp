#include "model/eol/StepMeasure.h"

#include "model/profile/RoleEvaluator.h"
#include "model/session/DeviceSession.h"

#include <cmath>

namespace opentop {

namespace {

const QString kCurrentSpeed = QStringLiteral("currentSpeed");
const QString kTargetSpeed = QStringLiteral("targetSpeed");
const QString kAlarm = QStringLiteral("alarmActive");
const QString kAlarmTable = QStringLiteral("alarm"); // the code table and records of alarms

QString number(double v)
{
    return LimitCheck::number(v);
}

} // namespace

StepMeasure::StepMeasure(DeviceSession* session, RunnerStates& states, int pollMs,
                         int maxFailedPolls, QObject* parent)
    : QObject(parent)
    , m_session(session)
    , m_states(states)
    , m_pollMs(pollMs)
    , m_maxFailedPolls(maxFailedPolls)
{
}

QString StepMeasure::labelOf(const QString& parameter) const
{
    const ParameterMeta* meta = m_session ? m_session->profile().parameter(parameter) : nullptr;
    return meta ? meta->label : parameter;
}

QString StepMeasure::recordLabelOf(const QString& parameter) const
{
    const ParameterMeta* meta = m_session ? m_session->profile().parameter(parameter) : nullptr;
    return meta ? meta->canonicalLabel : parameter;
}

QString StepMeasure::unitOf(const QString& parameter) const
{
    const ParameterMeta* meta = m_session ? m_session->profile().parameter(parameter) : nullptr;
    return meta ? meta->specFor(m_session->context()).canonicalUnit : QString();
}

void StepMeasure::record(const QString& quantity, double value, const QString& unit,
                         std::optional<double> lower, std::optional<double> upper, bool pass)
{
    Measurement m;
    m.machineNumber = m_session ? m_session->slave() : 0;
    m.step = m_step;
    m.quantity = quantity;
    m.value = value;
    m.unit = unit;
    m.lower = lower;
    m.upper = upper;
    m.pass = pass;
    emit measured(m);
}

void StepMeasure::poll(const QStringList& names, std::function<void(const Values&)> then, Done done)
{
    QStringList all = names;
    const ParameterMeta* alarm = RoleEvaluator::parameter(m_session->profile(), kAlarm);
    if (alarm && !all.contains(alarm->name))
        all << alarm->name;
    m_session->readMany(
        all, answer(m_states, [this, then, done](const DeviceSession::ReadManyOutcome& many) {
            Values values;
            QString error;
            for (auto it = many.results.cbegin(); it != many.results.cend(); ++it) {
                if (it.value().ok && it.value().value.valid)
                    values.insert(it.key(), it.value().value);
                else if (error.isEmpty())
                    error = it.value().error;
            }
            if (!error.isEmpty()) {
                if (++m_failedPolls >= m_maxFailedPolls) {
                    done(tr("%1: the drive stopped answering: %2").arg(m_step, error));
                    return;
                }
            } else {
                m_failedPolls = 0;
            }
            if (alarmIn(values)) {
                m_alarmSeen = true;
                failWithAlarm(tr("%1: the drive raised an alarm while running").arg(m_step), done);
                return;
            }
            then(values);
        }));
}

void StepMeasure::failWithAlarm(const QString& reason, Done done)
{
    // Named as the drive's panel shows it: the newest alarm record decoded by its code table.
    const Profile& profile = m_session->profile();
    const QVector<const ParameterMeta*> records = profile.records(kAlarmTable);
    const CodeTable* codes = profile.codeTable(kAlarmTable);
    if (records.isEmpty() || !codes) {
        done(reason);
        return;
    }
    m_session->read(records.first()->name,
                    answer(m_states, [reason, codes, done](const DeviceSession::Outcome& r) {
                        const CodeEntry* e = r.ok ? codes->find(qint64(r.value.raw)) : nullptr;
                        done(e ? tr("%1: %2 %3").arg(reason, e->panel, e->name) : reason);
                    }));
}

bool StepMeasure::alarmIn(const Values& values) const
{
    const std::optional<bool> alarm =
        RoleEvaluator::flag(m_session->profile(), kAlarm, [&values](const QString& name) {
            return values.contains(name) ? std::optional<double>(values.value(name).raw)
                                         : std::nullopt;
        });
    return alarm.value_or(false);
}

void StepMeasure::waitSpeed(const RecipeStep& step, Done done)
{
    const ParameterMeta* speed = RoleEvaluator::parameter(m_session->profile(), kCurrentSpeed);
    const ParameterMeta* target = RoleEvaluator::parameter(m_session->profile(), kTargetSpeed);
    if (!speed || (!step.target && !target)) {
        done(tr("%1: the drive has no speed to wait for").arg(m_step));
        return;
    }
    QStringList names{speed->name};
    if (!step.target)
        names << target->name;
    m_lastSpeed.reset();
    m_clock.start();
    const QString unit = unitOf(speed->name);
    // Polled from the wait's start on the period, as long as the wait's state lasts.
    m_states.every(
        m_pollMs, [this, step, names, speed, target, unit, done](std::function<void()> again) {
            poll(
                names,
                [this, step, speed, target, unit, done, again](const Values& values) {
                    const double elapsedS = m_clock.elapsed() / 1000.0;
                    std::optional<double> goal = step.target;
                    if (!goal && values.contains(target->name))
                        goal = values.value(target->name).number;
                    if (values.contains(speed->name)) {
                        m_lastSpeed = values.value(speed->name).number;
                        emit speedSampled(*m_lastSpeed, unit);
                    }
                    const QString quantity = tr("time to reach speed");
                    // A drive turning in reverse may report a negative speed.
                    if (goal && m_lastSpeed &&
                        std::abs(std::abs(*m_lastSpeed) - std::abs(*goal)) <= step.tolerance) {
                        record(quantity, elapsedS, tr("s"), 0.0, step.timeout, true);
                        done(QString());
                        return;
                    }
                    if (elapsedS < step.timeout) {
                        again();
                        return;
                    }
                    record(quantity, elapsedS, tr("s"), 0.0, step.timeout, false);
                    const QString last = m_lastSpeed ? number(*m_lastSpeed) : tr("unknown");
                    done(tr("%1: did not reach %2 %3 ±%4 %3 within %5 s (last read %6 %3)")
                             .arg(m_step, goal ? number(*goal) : tr("its target"), unit,
                                  number(step.tolerance), number(step.timeout), last));
                },
                done);
        });
}

void StepMeasure::hold(const RecipeStep& step, Done done)
{
    QStringList names;
    for (const RecipeLimit& l : step.limits)
        if (!names.contains(l.parameter))
            names << l.parameter;
    const ParameterMeta* speed = RoleEvaluator::parameter(m_session->profile(), kCurrentSpeed);
    if (speed && !names.contains(speed->name))
        names << speed->name;
    m_hold = LimitCheck(step.limits);
    m_clock.start();
    const qint64 durationMs = qint64(step.duration * 1000);
    m_states.every(m_pollMs, [this, names, speed, durationMs, done](std::function<void()> again) {
        poll(
            names,
            [this, speed, durationMs, done, again](const Values& values) {
                m_hold.add(values);
                if (speed && values.contains(speed->name))
                    emit speedSampled(values.value(speed->name).number, unitOf(speed->name));
                if (m_clock.elapsed() < durationMs) {
                    again();
                    return;
                }
                const LimitCheck::Verdict verdict =
                    m_hold.judge(m_session->profile(), m_session->context());
                for (const LimitCheck::Check& c : verdict.checks)
                    record(c.quantity, c.value, c.unit, c.lower, c.upper, c.pass);
                done(verdict.failure.isEmpty() ? QString()
                                               : tr("%1: %2").arg(m_step, verdict.failure));
            },
            done);
    });
}

void StepMeasure::noAlarm(Done done)
{
    const ParameterMeta* alarm = RoleEvaluator::parameter(m_session->profile(), kAlarm);
    if (!alarm) {
        done(tr("%1: the drive reports no alarms").arg(m_step));
        return;
    }
    m_session->read(alarm->name, answer(m_states, [this, done](const DeviceSession::Outcome& r) {
                        if (!r.ok) {
                            done(tr("%1: %2").arg(m_step, r.error));
                            return;
                        }
                        const bool now = alarmIn({{r.parameter, r.value}});
                        const bool alarmed = now || m_alarmSeen;
                        record(tr("alarms raised"), alarmed ? 1 : 0, QString(), std::nullopt, 0.0,
                               !alarmed);
                        done(alarmed ? tr("%1: the drive has an alarm").arg(m_step) : QString());
                    }));
}

void StepMeasure::read(const RecipeStep& step, Done done)
{
    if (step.limits.isEmpty()) {
        done(tr("%1: nothing to read").arg(m_step));
        return;
    }
    const RecipeLimit limit = step.limits.first();
    const auto judged = [this, step, limit, done](const DeviceSession::Outcome& r) {
        if (!r.ok) {
            done(tr("%1: %2").arg(m_step, r.error));
            return;
        }
        const QString label = labelOf(limit.parameter);
        const QString unit = unitOf(limit.parameter);
        if (!step.equals.isEmpty()) {
            const bool pass = r.value.text == step.equals;
            // The code as the value, the label it reads as in the quantity's name.
            record(tr("%1 (%2)").arg(recordLabelOf(limit.parameter), r.value.text), r.value.raw,
                   QString(), std::nullopt, std::nullopt, pass);
            done(pass ? QString()
                      : tr("%1: %2 reads \"%3\", expected \"%4\"")
                            .arg(m_step, label, r.value.text, step.equals));
            return;
        }
        const bool pass = LimitCheck::within(r.value.number, limit.lower, limit.upper);
        record(recordLabelOf(limit.parameter), r.value.number, unit, limit.lower, limit.upper,
               pass);
        done(pass ? QString()
                  : tr("%1: %2 reads %3 %4, %5")
                        .arg(m_step, label, number(r.value.number), unit,
                             LimitCheck::allowedText(limit.lower, limit.upper, unit))
                        .simplified());
    };
    m_session->read(limit.parameter, answer(m_states, judged));
}

void StepMeasure::stopAllowance(const RecipeStep& step, int selected, double unknownS,
                                std::function<void(double)> then)
{
    if (step.deceleration) {
        then(*step.deceleration + step.margin);
        return;
    }
    // Running data whose deceleration comes from a knob (the DBU's SPno1: the SD knob, not
    // readable): allow the knob's maximum (the profile's decelerationKnobs).
    if (selected) {
        if (const std::optional<double> knob =
                m_session->profile().knobDeceleration(selected - 1)) {
            then(*knob + step.margin);
            return;
        }
    }
    // The drive's own deceleration time of the running data it runs.
    const QString decel = QStringLiteral("spno%1.decel").arg(selected);
    if (!selected || !m_session->profile().parameter(decel)) {
        then(unknownS + step.margin);
        return;
    }
    m_session->read(decel,
                    answer(m_states, [step, unknownS, then](const DeviceSession::Outcome& r) {
                        then((r.ok ? r.value.number : unknownS) + step.margin);
                    }));
}

QString StepMeasure::stopTime(bool confirmed, const QString& detail, qint64 ms, double limitS)
{
    const double s = ms / 1000.0;
    const bool pass = confirmed && s <= limitS;
    record(tr("time to stop"), s, tr("s"), 0.0, limitS, pass);
    if (!confirmed)
        return tr("%1: %2").arg(m_step, detail);
    if (!pass)
        return tr("%1: stopped after %2 s, allowed at most %3 s")
            .arg(m_step, number(s), number(limitS));
    return QString();
}

} // namespace opentop
