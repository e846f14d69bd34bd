#include "model/eol/EolStepRunner.h"

#include "model/ModelLog.h"
#include "model/eol/Recipe.h"
#include "model/profile/RoleEvaluator.h"
#include "model/profile/ValueCodec.h"
#include "model/run/RunControl.h"
#include "model/session/DeviceSession.h"

#include <QTimer>
#include <algorithm>
#include <cmath>

namespace opentop {

namespace {

const QString kCurrentSpeed = QStringLiteral("currentSpeed");
const QString kTargetSpeed = QStringLiteral("targetSpeed");
const QString kAlarm = QStringLiteral("alarmActive");
const QString kPriority = QStringLiteral("motionPriority");
const QString kAlarmTable = QStringLiteral("alarm"); // the code table and records of alarms

QString number(double v)
{
    // Enough digits for a limit check to be read back exactly; no trailing zeros.
    return QString::number(v, 'g', 6);
}

bool withinLimits(double v, std::optional<double> lower, std::optional<double> upper)
{
    return (!lower || v >= *lower) && (!upper || v <= *upper);
}

// "allowed 1475–1525 r/min", "allowed at most 80 %", "allowed at least 1450 r/min".
QString allowedText(std::optional<double> lower, std::optional<double> upper, const QString& unit)
{
    QString text;
    if (lower && upper)
        text = EolStepRunner::tr("allowed %1–%2 %3").arg(number(*lower), number(*upper), unit);
    else if (upper)
        text = EolStepRunner::tr("allowed at most %1 %2").arg(number(*upper), unit);
    else if (lower)
        text = EolStepRunner::tr("allowed at least %1 %2").arg(number(*lower), unit);
    return text.trimmed();
}

} // namespace

void EolStepRunner::Stats::add(double v)
{
    min = count ? std::min(min, v) : v;
    max = count ? std::max(max, v) : v;
    sum += v;
    ++count;
}

EolStepRunner::EolStepRunner(DeviceSession* session, RunControl* run,
                             const QVector<RecipeStep>& steps, const Timing& timing,
                             QObject* parent)
    : QObject(parent)
    , m_session(session)
    , m_run(run)
    , m_steps(steps)
    , m_timing(timing)
{
}

void EolStepRunner::start(Done done)
{
    m_done = std::move(done);
    m_index = -1;
    m_result = {};
    const quint64 token = m_token;
    QTimer::singleShot(0, this, [this, token] {
        if (current(token))
            next();
    });
}

void EolStepRunner::abort(const QString& reason)
{
    if (!m_done)
        return;
    fail(reason);
}

QString EolStepRunner::stepText() const
{
    if (m_index < 0 || m_index >= m_steps.size())
        return QString();
    return tr("step %1 (%2)").arg(m_index + 1).arg(Recipe::stepTitle(m_steps[m_index].type));
}

QString EolStepRunner::labelOf(const QString& parameter) const
{
    const ParameterMeta* meta = m_session ? m_session->profile().parameter(parameter) : nullptr;
    return meta ? meta->label : parameter;
}

QString EolStepRunner::recordLabelOf(const QString& parameter) const
{
    const ParameterMeta* meta = m_session ? m_session->profile().parameter(parameter) : nullptr;
    return meta ? meta->canonicalLabel : parameter;
}

QString EolStepRunner::unitOf(const QString& parameter) const
{
    const ParameterMeta* meta = m_session ? m_session->profile().parameter(parameter) : nullptr;
    return meta ? meta->specFor(m_session->context()).canonicalUnit : QString();
}

void EolStepRunner::record(const QString& quantity, double value, const QString& unit,
                           std::optional<double> lower, std::optional<double> upper, bool pass)
{
    Measurement m;
    m.machineNumber = m_session ? m_session->slave() : 0;
    m.step = stepText();
    m.quantity = quantity;
    m.value = value;
    m.unit = unit;
    m.lower = lower;
    m.upper = upper;
    m.pass = pass;
    emit measured(m);
}

void EolStepRunner::next()
{
    if (!m_session) {
        fail(tr("the drive's session ended"));
        return;
    }
    ++m_index;
    if (m_index >= m_steps.size()) {
        finish(true);
        return;
    }
    const RecipeStep& step = m_steps[m_index];
    emit stepStarted(m_index, Recipe::stepTitle(step.type));
    const auto then = [this] { next(); };
    switch (step.type) {
    case RecipeStep::Type::Priority:
        runPriority();
        return;
    case RecipeStep::Type::Select:
        m_selected = step.spno;
        runCommand(int(RunControl::Action::Select), step.spno, QString(), then);
        return;
    case RecipeStep::Type::Speed:
        runCommand(int(RunControl::Action::Speed), 0, number(step.speed), then);
        return;
    case RecipeStep::Type::Start: {
        const auto direction = step.direction.compare(QLatin1String("ccw"), Qt::CaseInsensitive)
                                   ? RunControl::Action::Cw
                                   : RunControl::Action::Ccw;
        runCommand(int(direction), 0, QString(), [this, then] {
            runCommand(int(RunControl::Action::Start), 0, QString(), then);
        });
        return;
    }
    case RecipeStep::Type::WaitSpeed:
        runWaitSpeed(step);
        return;
    case RecipeStep::Type::Hold:
        runHold(step);
        return;
    case RecipeStep::Type::NoAlarm:
        runNoAlarm();
        return;
    case RecipeStep::Type::Stop:
        runStop(step);
        return;
    case RecipeStep::Type::Read:
        runRead(step);
        return;
    }
}

void EolStepRunner::runCommand(int action, int select, const QString& speed,
                               std::function<void()> then)
{
    RunControl::Command command;
    command.action = RunControl::Action(action);
    command.select = select;
    command.speed = speed;
    const auto a = command.action;
    // Sent: the motor may run even if the reply never comes.
    if (a == RunControl::Action::Start || a == RunControl::Action::Speed) {
        m_motion = true;
        m_stopped = false;
    }
    const quint64 token = m_token;
    m_run->execute(m_session, command,
                   [this, token, then = std::move(then)](const RunControl::Outcome& o) {
                       if (!current(token))
                           return;
                       if (!o.ok) {
                           QString why = o.error;
                           if (!o.deviceError.isEmpty())
                               why += QStringLiteral(" (%1)").arg(o.deviceError);
                           if (!o.explanation.isEmpty())
                               why += QStringLiteral(": ") + o.explanation;
                           fail(tr("%1: %2").arg(stepText(), why));
                           return;
                       }
                       then();
                   });
}

void EolStepRunner::runPriority()
{
    const ParameterMeta* meta = RoleEvaluator::parameter(m_session->profile(), kPriority);
    const ProfileRole* role = m_session->profile().role(kPriority);
    if (!meta || !role || !role->value) {
        fail(tr("%1: the drive has no communication priority").arg(stepText()));
        return;
    }
    const quint64 token = m_token;
    m_session->read(meta->name, [this, token, meta, role](const DeviceSession::Outcome& r) {
        if (!current(token))
            return;
        if (!r.ok) {
            fail(tr("%1: %2").arg(stepText(), r.error));
            return;
        }
        const ValueContext context = m_session->context();
        m_priorityBefore = RoleEvaluator::writeText(*meta, qint64(r.value.raw), context);
        DeviceSession::WriteOptions options;
        options.explicitCommand = true; // the recipe's step asks for it
        m_session->write(meta->name, RoleEvaluator::writeText(*meta, *role->value, context),
                         options, [this, token](const DeviceSession::Outcome& w) {
                             if (!current(token))
                                 return;
                             if (!w.ok) {
                                 fail(tr("%1: %2").arg(stepText(), w.error));
                                 return;
                             }
                             next();
                         });
    });
}

void EolStepRunner::poll(const QStringList& names,
                         std::function<void(const QHash<QString, ParamValue>&)> then)
{
    QStringList all = names;
    const ParameterMeta* alarm = RoleEvaluator::parameter(m_session->profile(), kAlarm);
    if (alarm && !all.contains(alarm->name))
        all << alarm->name;
    const quint64 token = m_token;
    m_session->readMany(
        all, [this, token, then = std::move(then)](const DeviceSession::ReadManyOutcome& many) {
            if (!current(token))
                return;
            QHash<QString, ParamValue> values;
            QString error;
            for (auto it = many.results.cbegin(); it != many.results.cend(); ++it) {
                if (it.value().ok && it.value().value.valid)
                    values.insert(it.key(), it.value().value);
                else if (error.isEmpty())
                    error = it.value().error;
            }
            if (!error.isEmpty()) {
                if (++m_failedPolls >= m_timing.maxFailedPolls) {
                    fail(tr("%1: the drive stopped answering: %2").arg(stepText(), error));
                    return;
                }
            } else {
                m_failedPolls = 0;
            }
            if (alarmIn(values)) {
                m_alarmSeen = true;
                failWithAlarm(tr("%1: the drive raised an alarm while running").arg(stepText()));
                return;
            }
            then(values);
        });
}

void EolStepRunner::failWithAlarm(const QString& reason)
{
    // Named as the drive's panel shows it: the newest alarm record decoded by its code table.
    const Profile& profile = m_session->profile();
    const QVector<const ParameterMeta*> records = profile.records(kAlarmTable);
    const CodeTable* codes = profile.codeTable(kAlarmTable);
    if (records.isEmpty() || !codes) {
        fail(reason);
        return;
    }
    const quint64 token = m_token;
    m_session->read(records.first()->name,
                    [this, token, reason, codes](const DeviceSession::Outcome& r) {
                        if (!current(token))
                            return;
                        const CodeEntry* e = r.ok ? codes->find(qint64(r.value.raw)) : nullptr;
                        fail(e ? tr("%1: %2 %3").arg(reason, e->panel, e->name) : reason);
                    });
}

bool EolStepRunner::alarmIn(const QHash<QString, ParamValue>& values) const
{
    const std::optional<bool> alarm =
        RoleEvaluator::flag(m_session->profile(), kAlarm, [&values](const QString& name) {
            return values.contains(name) ? std::optional<double>(values.value(name).raw)
                                         : std::nullopt;
        });
    return alarm.value_or(false);
}

void EolStepRunner::runWaitSpeed(const RecipeStep& step)
{
    const ParameterMeta* speed = RoleEvaluator::parameter(m_session->profile(), kCurrentSpeed);
    const ParameterMeta* target = RoleEvaluator::parameter(m_session->profile(), kTargetSpeed);
    if (!speed || (!step.target && !target)) {
        fail(tr("%1: the drive has no speed to wait for").arg(stepText()));
        return;
    }
    QStringList names{speed->name};
    if (!step.target)
        names << target->name;
    auto since = std::make_shared<QElapsedTimer>();
    since->start();
    auto last = std::make_shared<std::optional<double>>();
    const QString unit = unitOf(speed->name);
    const QString quantity = tr("time to reach speed");
    const double timeoutS = step.timeout;
    auto round = std::make_shared<std::function<void()>>();
    const quint64 token = m_token;
    // The function holds itself only weakly (a strong self-capture is a cycle that never frees);
    // the poll and the timer it waits in hold it while a round is under way.
    *round = [this, token, step, names, speed, target, since, last, unit, quantity, timeoutS,
              weak = std::weak_ptr<std::function<void()>>(round)] {
        const auto again = weak.lock();
        if (!again)
            return;
        poll(names, [=](const QHash<QString, ParamValue>& values) {
            const double elapsedS = since->elapsed() / 1000.0;
            std::optional<double> goal = step.target;
            if (!goal && values.contains(target->name))
                goal = values.value(target->name).number;
            if (values.contains(speed->name)) {
                *last = values.value(speed->name).number;
                emit speedSampled(**last, unit);
            }
            // A drive turning in reverse may report a negative speed.
            if (goal && *last && std::abs(std::abs(**last) - std::abs(*goal)) <= step.tolerance) {
                record(quantity, elapsedS, tr("s"), 0.0, timeoutS, true);
                next();
                return;
            }
            if (elapsedS >= timeoutS) {
                record(quantity, elapsedS, tr("s"), 0.0, timeoutS, false);
                const QString lastText = *last ? number(**last) : tr("unknown");
                fail(tr("%1: did not reach %2 %3 ±%4 %3 within %5 s (last read %6 %3)")
                         .arg(stepText(), goal ? number(*goal) : tr("its target"), unit,
                              number(step.tolerance), number(timeoutS), lastText));
                return;
            }
            const int waitMs =
                std::max(0, m_timing.pollMs - int(since->elapsed() % m_timing.pollMs));
            QTimer::singleShot(waitMs, this, [this, token, again] {
                if (current(token))
                    (*again)();
            });
        });
    };
    (*round)();
}

void EolStepRunner::runHold(const RecipeStep& step)
{
    QStringList names;
    for (const RecipeLimit& l : step.limits)
        if (!names.contains(l.parameter))
            names << l.parameter;
    const ParameterMeta* speed = RoleEvaluator::parameter(m_session->profile(), kCurrentSpeed);
    if (speed && !names.contains(speed->name))
        names << speed->name;
    auto stats = std::make_shared<QHash<QString, Stats>>();
    auto since = std::make_shared<QElapsedTimer>();
    since->start();
    const qint64 durationMs = qint64(step.duration * 1000);
    auto round = std::make_shared<std::function<void()>>();
    const quint64 token = m_token;
    *round = [this, token, step, names, speed, stats, since, durationMs,
              weak = std::weak_ptr<std::function<void()>>(round)] {
        const auto again = weak.lock(); // held by the poll and the timer (see runWaitSpeed)
        if (!again)
            return;
        poll(names, [=](const QHash<QString, ParamValue>& values) {
            for (auto it = values.cbegin(); it != values.cend(); ++it)
                (*stats)[it.key()].add(it.value().number);
            if (speed && values.contains(speed->name))
                emit speedSampled(values.value(speed->name).number, unitOf(speed->name));
            if (since->elapsed() < durationMs) {
                const int waitMs =
                    std::max(0, m_timing.pollMs - int(since->elapsed() % m_timing.pollMs));
                QTimer::singleShot(waitMs, this, [this, token, again] {
                    if (current(token))
                        (*again)();
                });
                return;
            }
            QString firstFailure;
            for (const RecipeLimit& l : step.limits) {
                const Stats s = stats->value(l.parameter);
                const QString quantity =
                    QStringLiteral("%1 %2").arg(recordLabelOf(l.parameter), l.statistic);
                const QString unit = unitOf(l.parameter);
                if (!s.count) {
                    if (firstFailure.isEmpty())
                        firstFailure = tr("%1 could not be read").arg(labelOf(l.parameter));
                    continue;
                }
                const double v = l.statistic == QLatin1String("min")   ? s.min
                                 : l.statistic == QLatin1String("max") ? s.max
                                                                       : s.sum / s.count;
                const bool pass = withinLimits(v, l.lower, l.upper);
                record(quantity, v, unit, l.lower, l.upper, pass);
                if (!pass && firstFailure.isEmpty())
                    firstFailure =
                        tr("%1 %2 %3, %4")
                            .arg(quantity, number(v), unit, allowedText(l.lower, l.upper, unit))
                            .simplified();
            }
            if (!firstFailure.isEmpty()) {
                fail(tr("%1: %2").arg(stepText(), firstFailure));
                return;
            }
            next();
        });
    };
    (*round)();
}

void EolStepRunner::runNoAlarm()
{
    const ParameterMeta* alarm = RoleEvaluator::parameter(m_session->profile(), kAlarm);
    if (!alarm) {
        fail(tr("%1: the drive reports no alarms").arg(stepText()));
        return;
    }
    const quint64 token = m_token;
    m_session->read(alarm->name, [this, token](const DeviceSession::Outcome& r) {
        if (!current(token))
            return;
        if (!r.ok) {
            fail(tr("%1: %2").arg(stepText(), r.error));
            return;
        }
        const QHash<QString, ParamValue> values{{r.parameter, r.value}};
        const bool now = alarmIn(values);
        record(tr("alarms raised"), now || m_alarmSeen ? 1 : 0, QString(), std::nullopt, 0.0,
               !now && !m_alarmSeen);
        if (now || m_alarmSeen) {
            fail(tr("%1: the drive has an alarm").arg(stepText()));
            return;
        }
        next();
    });
}

void EolStepRunner::runStop(const RecipeStep& step)
{
    const auto stopWithin = [this, step](double decelerationS) {
        const double limitS = decelerationS + step.margin;
        stopMotor(
            [this, limitS](bool confirmed, const QString& detail, qint64 ms) {
                const double s = ms / 1000.0;
                const bool pass = confirmed && s <= limitS;
                record(tr("time to stop"), s, tr("s"), 0.0, limitS, pass);
                if (!confirmed) {
                    m_result.stopConfirmed = false;
                    fail(tr("%1: %2").arg(stepText(), detail));
                    return;
                }
                if (!pass) {
                    fail(tr("%1: stopped after %2 s, allowed at most %3 s")
                             .arg(stepText(), number(s), number(limitS)));
                    return;
                }
                next();
            },
            int(step.margin * 1000));
    };
    if (step.deceleration) {
        stopWithin(*step.deceleration);
        return;
    }
    // Running data whose deceleration comes from a knob (the DBU's SPno1: the SD knob, not
    // readable): allow the knob's maximum (the profile's decelerationKnobs).
    if (m_selected) {
        if (const std::optional<double> knob =
                m_session->profile().knobDeceleration(m_selected - 1)) {
            stopWithin(*knob);
            return;
        }
    }
    // The drive's own deceleration time of the running data it runs.
    const QString decel = QStringLiteral("spno%1.decel").arg(m_selected);
    if (!m_selected || !m_session->profile().parameter(decel)) {
        stopWithin(m_timing.stop.unknownDecelMs / 1000.0);
        return;
    }
    const quint64 token = m_token;
    m_session->read(decel, [this, token, stopWithin](const DeviceSession::Outcome& r) {
        if (!current(token))
            return;
        stopWithin(r.ok ? r.value.number : m_timing.stop.unknownDecelMs / 1000.0);
    });
}

void EolStepRunner::runRead(const RecipeStep& step)
{
    if (step.limits.isEmpty()) {
        fail(tr("%1: nothing to read").arg(stepText()));
        return;
    }
    const RecipeLimit limit = step.limits.first();
    const quint64 token = m_token;
    m_session->read(limit.parameter, [this, token, step, limit](const DeviceSession::Outcome& r) {
        if (!current(token))
            return;
        if (!r.ok) {
            fail(tr("%1: %2").arg(stepText(), r.error));
            return;
        }
        const QString label = labelOf(limit.parameter);
        const QString unit = unitOf(limit.parameter);
        if (!step.equals.isEmpty()) {
            const bool pass = r.value.text == step.equals;
            // The code as the value, the label it reads as in the quantity's name.
            record(tr("%1 (%2)").arg(recordLabelOf(limit.parameter), r.value.text), r.value.raw,
                   QString(), std::nullopt, std::nullopt, pass);
            if (!pass) {
                fail(tr("%1: %2 reads \"%3\", expected \"%4\"")
                         .arg(stepText(), label, r.value.text, step.equals));
                return;
            }
            next();
            return;
        }
        const bool pass = withinLimits(r.value.number, limit.lower, limit.upper);
        record(recordLabelOf(limit.parameter), r.value.number, unit, limit.lower, limit.upper,
               pass);
        if (!pass) {
            fail(tr("%1: %2 reads %3 %4, %5")
                     .arg(stepText(), label, number(r.value.number), unit,
                          allowedText(limit.lower, limit.upper, unit))
                     .simplified());
            return;
        }
        next();
    });
}

void EolStepRunner::stopMotor(std::function<void(bool, const QString&, qint64)> then, int marginMs)
{
    const quint64 token = m_token;
    auto sinceStop = std::make_shared<QElapsedTimer>();
    sinceStop->start();
    RunControl::Command stop;
    stop.action = RunControl::Action::Stop;
    m_run->execute(
        m_session, stop, [this, token, then, sinceStop, marginMs](const RunControl::Outcome& o) {
            if (!current(token))
                return;
            if (!o.ok) {
                then(false, tr("the stop command failed: %1").arg(o.error), sinceStop->elapsed());
                return;
            }
            StopConfirmer::Timing timing = m_timing.stop;
            if (marginMs >= 0)
                timing.marginMs = marginMs;
            auto* confirmer = new StopConfirmer(m_session, *sinceStop, timing, this);
            confirmer->start([this, token, then, confirmer](const StopResult& r) {
                confirmer->deleteLater();
                if (!current(token))
                    return;
                const bool stopped = r.state == StopResult::State::Stopped;
                if (stopped)
                    m_stopped = true;
                then(stopped,
                     stopped ? tr("stopped after %1 s").arg(number(r.elapsedMs / 1000.0))
                             : tr("not confirmed stopped: %1").arg(r.detail),
                     r.elapsedMs);
            });
        });
}

void EolStepRunner::givePriorityBack(std::function<void()> then)
{
    const ParameterMeta* meta = RoleEvaluator::parameter(m_session->profile(), kPriority);
    if (!m_priorityBefore || !meta || !m_session) {
        then();
        return;
    }
    const QString text = *m_priorityBefore;
    m_priorityBefore.reset();
    DeviceSession::WriteOptions options;
    options.explicitCommand = true;
    m_session->write(meta->name, text, options, [this, then](const DeviceSession::Outcome& w) {
        if (!w.ok) {
            qCWarning(lcModel) << "priority not given back" << w.error;
            if (m_result.ok)
                m_result.failure =
                    tr("communication priority could not be given back: %1").arg(w.error);
            m_result.ok = false;
        }
        then();
    });
}

void EolStepRunner::fail(const QString& reason)
{
    if (!m_done)
        return;
    if (m_result.failure.isEmpty())
        m_result.failure = reason;
    ++m_token; // whatever step was in progress ends here
    if (!m_session) {
        m_result.stopConfirmed = !m_motion || m_stopped;
        finish(false);
        return;
    }
    if (!m_motion || m_stopped) {
        givePriorityBack([this] { finish(false); });
        return;
    }
    // The motor may be turning: stop it at once and say what became of it.
    stopMotor([this](bool confirmed, const QString& detail, qint64) {
        m_result.stopConfirmed = confirmed;
        m_result.stopDetail = detail;
        if (confirmed)
            givePriorityBack([this] { finish(false); });
        else
            finish(false);
    });
}

void EolStepRunner::finish(bool ok)
{
    if (!m_done)
        return;
    if (ok && m_motion && !m_stopped) {
        // Steps that leave the motor running are refused by the checker; stop anyway.
        fail(tr("the steps ended with the motor running"));
        return;
    }
    if (ok && m_priorityBefore) {
        m_result.ok = true;
        givePriorityBack([this] { finish(m_result.ok); });
        return;
    }
    ++m_token;
    m_result.ok = ok && m_result.failure.isEmpty();
    Done done = std::move(m_done);
    m_done = nullptr;
    done(m_result);
}

} // namespace opentop
