#include "model/eol/EolStepRunner.h"

#include "model/ModelLog.h"
#include "model/eol/Recipe.h"
#include "model/profile/RoleEvaluator.h"
#include "model/session/DeviceSession.h"

#include <QElapsedTimer>
#include <utility>

namespace opentop {

namespace {

const QString kPriority = QStringLiteral("motionPriority");

RunControl::Command command(RunControl::Action action, int select = 0, const QString& speed = {})
{
    RunControl::Command c;
    c.action = action;
    c.select = select;
    c.speed = speed;
    return c;
}

} // namespace

EolStepRunner::EolStepRunner(DeviceSession* session, RunControl* run,
                             const QVector<RecipeStep>& steps, const Timing& timing,
                             QObject* parent)
    : QObject(parent)
    , m_session(session)
    , m_run(run)
    , m_steps(steps)
    , m_timing(timing)
    , m_states(QStringLiteral("EolStepRunner"))
    , m_measure(session, m_states, timing.pollMs, timing.maxFailedPolls)
{
    connect(&m_measure, &StepMeasure::measured, this, &EolStepRunner::measured);
    connect(&m_measure, &StepMeasure::speedSampled, this, &EolStepRunner::speedSampled);
    addStates();
}

EolStepRunner::~EolStepRunner()
{
    // Deleted while its motor may turn and its session lives on: the stop is sent without
    // waiting (the session's answers find this runner gone). The priority stays with the bus:
    // it is given back only after a confirmed stop.
    if (!m_done || !m_session || !m_states.motionMayBeOn())
        return;
    const RunControl::Plan stop = RunControl::plan(*m_session, command(RunControl::Action::Stop));
    if (stop.failure != RunControl::Failure::None)
        return;
    DeviceSession::WriteOptions options;
    options.explicitCommand = true;
    options.verify = false;
    m_session->write(stop.meta->name, stop.text, options, [](const DeviceSession::Outcome&) {});
}

void EolStepRunner::addStates()
{
    // A step's state: the step announced, then run; a measuring step's verdict decides.
    const auto step = [this](State state, const char* name,
                             std::function<void(const RecipeStep&)> run) {
        m_states.add(state, name, [this, state, run] { enterStep(state, run); });
    };
    const auto judged = [this] { return answer([this](const QString& f) { verdict(f); }); };
    step(Priority, "priority", [this](const RecipeStep&) { runPriority(); });
    step(Command, "command", [this](const RecipeStep& s) { runCommands(s); });
    step(WaitSpeed, "wait speed",
         [this, judged](const RecipeStep& s) { m_measure.waitSpeed(s, judged()); });
    step(Hold, "hold", [this, judged](const RecipeStep& s) { m_measure.hold(s, judged()); });
    step(NoAlarm, "no alarm", [this, judged](const RecipeStep&) { m_measure.noAlarm(judged()); });
    step(StopStep, "stop", [this](const RecipeStep& s) { runStop(s); });
    step(Read, "read", [this, judged](const RecipeStep& s) { m_measure.read(s, judged()); });
    // The exits, in this order; fail() enters the first that applies.
    m_states.add(Stopping, "stopping", [this] { enterStopping(); });
    m_states.add(GivingBack, "giving back", [this] { enterGivingBack(); });
    m_states.add(Finished, "done", [this] { enterDone(); });
}

void EolStepRunner::start(Done done)
{
    m_done = std::move(done);
    m_index = 0;
    m_result = {};
    m_result.ok = m_steps.isEmpty(); // no steps: passed at once, as after the last step
    m_states.start(m_steps.isEmpty() ? afterStop() : stateOf(m_steps.at(0)));
}

EolStepRunner::State EolStepRunner::stateOf(const RecipeStep& step)
{
    switch (step.type) {
    case RecipeStep::Type::Priority:
        return Priority;
    case RecipeStep::Type::WaitSpeed:
        return WaitSpeed;
    case RecipeStep::Type::Hold:
        return Hold;
    case RecipeStep::Type::NoAlarm:
        return NoAlarm;
    case RecipeStep::Type::Stop:
        return StopStep;
    case RecipeStep::Type::Read:
        return Read;
    case RecipeStep::Type::Select:
    case RecipeStep::Type::Speed:
    case RecipeStep::Type::Start:
        break;
    }
    return Command; // select, speed and start: their run commands
}

QString EolStepRunner::stepText() const
{
    if (m_index < 0 || m_index >= m_steps.size())
        return QString();
    return tr("step %1 (%2)").arg(m_index + 1).arg(Recipe::stepTitle(m_steps[m_index].type));
}

void EolStepRunner::enterStep(State state, const std::function<void(const RecipeStep&)>& run)
{
    if (!m_session) {
        fail(tr("the drive's session ended"));
        return;
    }
    const RecipeStep step = m_steps.at(m_index);
    m_measure.setStep(stepText());
    emit stepStarted(m_index, Recipe::stepTitle(step.type));
    if (m_states.state() == state) // not aborted by a receiver of the signal
        run(step);
}

void EolStepRunner::verdict(const QString& failure)
{
    if (failure.isEmpty())
        next();
    else
        fail(failure);
}

// The step passed: the next one, or the end of the steps.
void EolStepRunner::next()
{
    if (!m_done || exiting())
        return;
    if (!m_session) {
        fail(tr("the drive's session ended"));
        return;
    }
    if (++m_index < m_steps.size()) {
        m_states.go(stateOf(m_steps.at(m_index)));
        return;
    }
    if (m_states.motionMayBeOn()) {
        // Steps that leave the motor running are refused by the checker; stop anyway.
        fail(tr("the steps ended with the motor running"));
        return;
    }
    m_result.ok = true;
    m_states.go(afterStop());
}

void EolStepRunner::runCommands(const RecipeStep& step)
{
    QVector<RunControl::Command> commands;
    if (step.type == RecipeStep::Type::Select) {
        m_selected = step.spno;
        commands << command(RunControl::Action::Select, step.spno);
    } else if (step.type == RecipeStep::Type::Speed) {
        commands << command(RunControl::Action::Speed, 0, LimitCheck::number(step.speed));
    } else {
        const bool cw = step.direction.compare(QLatin1String("ccw"), Qt::CaseInsensitive);
        commands << command(cw ? RunControl::Action::Cw : RunControl::Action::Ccw)
                 << command(RunControl::Action::Start);
    }
    sendCommands(commands);
}

void EolStepRunner::sendCommands(QVector<RunControl::Command> commands)
{
    if (commands.isEmpty()) {
        next();
        return;
    }
    const RunControl::Command c = commands.takeFirst();
    // Sent: the motor may run even if the reply never comes.
    if (c.action == RunControl::Action::Start || c.action == RunControl::Action::Speed)
        m_states.motionSent();
    m_run->execute(m_session, c, answer([this, commands](const RunControl::Outcome& o) {
                       if (!o.ok) {
                           QString why = o.error;
                           if (!o.deviceError.isEmpty())
                               why += QStringLiteral(" (%1)").arg(o.deviceError);
                           if (!o.explanation.isEmpty())
                               why += QStringLiteral(": ") + o.explanation;
                           fail(tr("%1: %2").arg(stepText(), why));
                           return;
                       }
                       sendCommands(commands);
                   }));
}

void EolStepRunner::runPriority()
{
    const ParameterMeta* meta = RoleEvaluator::parameter(m_session->profile(), kPriority);
    const ProfileRole* role = m_session->profile().role(kPriority);
    if (!meta || !role || !role->value) {
        fail(tr("%1: the drive has no communication priority").arg(stepText()));
        return;
    }
    m_session->read(
        meta->name, answer([this, meta, role](const DeviceSession::Outcome& r) {
            if (!r.ok) {
                fail(tr("%1: %2").arg(stepText(), r.error));
                return;
            }
            const ValueContext context = m_session->context();
            m_priorityBefore = RoleEvaluator::writeText(*meta, qint64(r.value.raw), context);
            DeviceSession::WriteOptions options;
            options.explicitCommand = true; // the recipe's step asks for it
            m_session->write(meta->name, RoleEvaluator::writeText(*meta, *role->value, context),
                             options, answer([this](const DeviceSession::Outcome& w) {
                                 if (!w.ok) {
                                     fail(tr("%1: %2").arg(stepText(), w.error));
                                     return;
                                 }
                                 next();
                             }));
        }));
}

void EolStepRunner::runStop(const RecipeStep& step)
{
    const double unknownS = m_timing.stop.unknownDecelMs / 1000.0;
    m_measure.stopAllowance(
        step, m_selected, unknownS, answer([this, step](double limitS) {
            stopMotor(int(step.margin * 1000),
                      [this, limitS](bool confirmed, const QString& detail, qint64 ms) {
                          if (!confirmed)
                              m_result.stopConfirmed = false;
                          verdict(m_measure.stopTime(confirmed, detail, ms, limitS));
                      });
        }));
}

// The stop command, then its confirmation (StopConfirmer); `marginMs` < 0: the timing's margin.
void EolStepRunner::stopMotor(int marginMs, Stopped then)
{
    QElapsedTimer sinceStop;
    sinceStop.start();
    m_run->execute(
        m_session, command(RunControl::Action::Stop),
        answer([this, then, sinceStop, marginMs](const RunControl::Outcome& o) {
            if (!o.ok) {
                then(false, tr("the stop command failed: %1").arg(o.error), sinceStop.elapsed());
                return;
            }
            StopConfirmer::Timing timing = m_timing.stop;
            if (marginMs >= 0)
                timing.marginMs = marginMs;
            auto* confirmer = new StopConfirmer(m_session, sinceStop, timing, this);
            const auto confirmed = answer([this, then](const StopResult& r) {
                const bool stopped = r.state == StopResult::State::Stopped;
                if (stopped)
                    m_states.stopConfirmed();
                then(stopped,
                     stopped
                         ? tr("stopped after %1 s").arg(LimitCheck::number(r.elapsedMs / 1000.0))
                         : tr("not confirmed stopped: %1").arg(r.detail),
                     r.elapsedMs);
            });
            confirmer->start([confirmer, confirmed](const StopResult& r) {
                confirmer->deleteLater();
                confirmed(r);
            });
        }));
}

// The one way out: whatever was under way ends here (its answers are dropped as its state is
// left); the motor is stopped first when motion may be on, then the priority given back.
void EolStepRunner::fail(const QString& reason)
{
    if (!m_done)
        return;
    if (m_result.failure.isEmpty())
        m_result.failure = reason;
    m_result.ok = false;
    if (exiting())
        return; // already on its way out: the stop and the priority carry on
    if (!m_session) {
        m_result.stopConfirmed = !m_states.motionMayBeOn();
        m_states.go(Finished);
        return;
    }
    m_states.go(m_states.motionMayBeOn() ? Stopping : afterStop());
}

void EolStepRunner::enterStopping()
{
    // The motor may be turning: stop it at once and say what became of it.
    stopMotor(-1, [this](bool confirmed, const QString& detail, qint64) {
        m_result.stopConfirmed = confirmed;
        m_result.stopDetail = detail;
        m_states.go(confirmed ? afterStop() : Finished);
    });
}

void EolStepRunner::enterGivingBack()
{
    const ParameterMeta* meta =
        m_session ? RoleEvaluator::parameter(m_session->profile(), kPriority) : nullptr;
    const std::optional<QString> before = std::exchange(m_priorityBefore, std::nullopt);
    if (!meta || !before) {
        m_states.go(Finished);
        return;
    }
    DeviceSession::WriteOptions options;
    options.explicitCommand = true;
    m_session->write(
        meta->name, *before, options, answer([this](const DeviceSession::Outcome& w) {
            if (!w.ok) {
                qCWarning(lcModel) << "priority not given back" << w.error;
                if (m_result.ok)
                    m_result.failure =
                        tr("communication priority could not be given back: %1").arg(w.error);
                m_result.ok = false;
            }
            m_states.go(Finished);
        }));
}

void EolStepRunner::enterDone()
{
    m_result.ok = m_result.ok && m_result.failure.isEmpty();
    m_states.end(); // nothing pending any more
    Done done = std::move(m_done);
    m_done = nullptr;
    done(m_result);
}

} // namespace opentop
