#include "model/tuning/TuningDrive.h"

#include "model/ModelLog.h"

#include <QTimer>

#include <cmath>
#include <utility>

namespace opentop {

TuningDrive::TuningDrive(DeviceSession* session, const TuningSpec& spec, QObject* parent)
    : QObject(parent)
    , m_session(session)
    , m_spec(spec)
    , m_states(new RunnerStates(QStringLiteral("tuning test"), this))
{
    m_states->add(Prepare, "prepare", [this] { prepare(); });
    m_states->add(SetCommLoss, "set comm-loss", [this] { setCommLoss(); });
    m_states->add(StopMotor, "stop motor", [this] { stopMotor(); });
    m_states->add(RestoreMode, "restore mode", [this] {
        writeNumber(m_spec.speedMode, *m_run.originalMode, [this](bool) { restoreOrReport(true); });
    });
    m_states->add(RestoreCommLoss, "restore comm-loss", [this] {
        writeNumber(m_spec.commLossTime, *m_run.originalCommLoss,
                    [this](bool) { m_states->go(Reported); });
    });
    m_states->add(Reported, "reported", [this] { report(); });
}

TuningDrive::~TuningDrive()
{
    // Gone while a test runs (its page or command torn down): the motor must not go on. The
    // stop is sent without waiting; the session's answers find the states gone.
    if (isRunning() && m_session && !exiting()) {
        DeviceSession::WriteOptions options;
        options.explicitCommand = true;
        options.verify = false;
        m_session->write(m_spec.command, QStringLiteral("0"), options,
                         [](const DeviceSession::Outcome&) {});
    }
    m_states->end();
}

bool TuningDrive::refuseIfRunning(const Done& done)
{
    if (!isRunning())
        return false;
    Result r;
    r.error = tr("a tuning test is already running");
    QTimer::singleShot(0, this, [done, r] { done(r); });
    return true;
}

void TuningDrive::begin(Done done, int first)
{
    m_done = std::move(done);
    m_run = Run();
    m_run.first = first;
    m_run.clock.start();
    m_run.origin = m_clock ? m_clock() : 0;
    // Entered at once, as the runner always did (its first phase and read before the start
    // returns): start() forgets the last test's trail and motion, go() enters now, and the
    // entry start() queued finds its state left and does nothing.
    m_states->start(Prepare);
    m_states->go(Prepare);
}

bool TuningDrive::exiting() const
{
    const int s = m_states->state();
    return s == StopMotor || s == RestoreMode || s == RestoreCommLoss || s == Reported;
}

double TuningDrive::nowMs() const
{
    return m_clock ? m_clock() - m_run.origin : m_run.clock.nsecsElapsed() / 1e6;
}

double TuningDrive::feedbackScale() const
{
    const ParameterMeta* meta = m_session->profile().parameter(m_spec.command);
    return meta ? meta->specFor(m_session->context()).scale : 1;
}

void TuningDrive::prepare()
{
    announce(tr("Reading the drive's settings"));
    m_session->readMany(
        QStringList{m_spec.speedMode, m_spec.commLossTime} + m_spec.gainParameters() +
            (m_spec.currentLimit.isEmpty() ? QStringList() : QStringList{m_spec.currentLimit}),
        answer([this](const DeviceSession::ReadManyOutcome& r) { prepared(r); }));
}

void TuningDrive::prepared(const DeviceSession::ReadManyOutcome& r)
{
    if (r.failed) { // nothing moved yet: no stop
        fail(tr("could not read the drive's settings: %1")
                 .arg(r.results.value(r.order.value(0)).error),
             false);
        return;
    }
    m_run.originalMode = r.results.value(m_spec.speedMode).value.raw;
    m_run.originalCommLoss = r.results.value(m_spec.commLossTime).value.number;
    if (!m_spec.currentLimit.isEmpty())
        m_run.currentLimit = r.results.value(m_spec.currentLimit).value.number;
    PidGains& g = m_run.result.gains;
    g.p = r.results.value(m_spec.gainP).value.number;
    g.i = r.results.value(m_spec.gainI).value.number;
    g.d = r.results.value(m_spec.gainD).value.number;
    g.dPeriodMs = int(r.results.value(m_spec.dPeriod).value.number);
    if (!m_spec.closedLoop(int(*m_run.originalMode))) {
        fail(notClosedLoop(), false);
        return;
    }
    m_run.closedScale = feedbackScale();
    const ParameterMeta* unitMeta =
        m_session->profile().parameter(m_spec.closedLoop(int(*m_run.originalMode))->feedback);
    m_run.result.speedUnit = unitMeta ? unitMeta->specFor(m_session->context()).unit : QString();
    // From here the test has the motor: every end stops it and waits for the stop, a plan
    // refused or a failed write as well (the drive may be turning in its closed-loop mode).
    m_states->motionSent();
    const double loss = *m_run.originalCommLoss;
    m_states->go(loss > 0 && loss <= m_limits.commLossS ? m_run.first : SetCommLoss);
}

QString TuningDrive::notClosedLoop() const
{
    QStringList modes;
    const ParameterMeta* modeMeta = m_session->profile().parameter(m_spec.speedMode);
    for (const TuningSpec::ClosedLoopMode& m : m_spec.closedLoopModes) {
        QString label = QString::number(m.mode);
        for (const EnumOption& o :
             modeMeta ? modeMeta->specFor(m_session->context()).options : QVector<EnumOption>())
            if (o.value == m.mode)
                label = QStringLiteral("%1 (%2)").arg(o.label).arg(m.mode);
        modes << label;
    }
    return tr("the drive is not in a closed-loop speed mode: set %1 (%2) to %3 first")
        .arg(modeMeta ? modeMeta->label : m_spec.speedMode, m_spec.speedMode,
             modes.join(tr(" or ")));
}

void TuningDrive::setCommLoss()
{
    emit phase(tr("Setting the communication-loss braking time to %1 s").arg(m_limits.commLossS));
    writeNumber(m_spec.commLossTime, m_limits.commLossS, [this](bool) {
        m_run.commLossChanged = true;
        m_states->go(m_run.first);
    });
}

void TuningDrive::writeNumber(const QString& parameter, double value,
                              std::function<void(bool)> then)
{
    DeviceSession::WriteOptions options;
    options.explicitCommand = true;
    m_session->write(parameter, QString::number(value, 'g', 10), options,
                     answer([this, then](const DeviceSession::Outcome& o) {
                         if (!o.ok && !exiting()) {
                             fail(o.error);
                             return;
                         }
                         then(o.ok);
                     }));
}

void TuningDrive::command(double engineering, std::function<void()> then)
{
    const double step = feedbackScale(); // whole raw units of the present mode
    writeNumber(m_spec.command, step > 0 ? std::round(engineering / step) * step : engineering,
                [then](bool) { then(); });
}

void TuningDrive::setMode(int mode, std::function<void()> then)
{
    writeNumber(m_spec.speedMode, mode, [this, then](bool) {
        m_run.modeChanged = true;
        then();
    });
}

void TuningDrive::record(const TuningSample& sample)
{
    m_run.result.samples << sample;
    emit sampled(sample);
}

void TuningDrive::poll(std::function<void(const TuningSample&)> then, std::function<void()> lost)
{
    const TuningSpec::ClosedLoopMode* loop =
        m_spec.closedLoop(m_run.originalMode ? int(*m_run.originalMode)
                                             : int(m_session->cachedValue(m_spec.speedMode).raw));
    const QString feedback = loop ? loop->feedback : QString();
    m_session->readMany(
        {feedback, m_spec.loadCurrent, m_spec.output},
        answer([this, feedback, then, lost](const DeviceSession::ReadManyOutcome& r) {
            if (r.failed) {
                if (++m_run.failedPolls >= kMaxFailedPolls) {
                    if (!exiting()) {
                        fail(tr("the drive stopped answering: %1")
                                 .arg(r.results.value(feedback).error));
                        return;
                    }
                    if (lost) {
                        lost();
                        return;
                    }
                }
                m_states->after(10, [this, then, lost] { poll(then, lost); });
                return;
            }
            m_run.failedPolls = 0;
            TuningSample s;
            s.tMs = nowMs() - m_run.t0;
            s.speed = r.results.value(feedback).value.number;
            s.current = r.results.value(m_spec.loadCurrent).value.number;
            s.output = r.results.value(m_spec.output).value.number;
            if (!exiting()) {
                if (m_limits.maxSpeed > 0 && std::abs(s.speed) > m_limits.maxSpeed) {
                    fail(tr("speed %1 %2 beyond the test's limit %3 %2: stopped at once")
                             .arg(s.speed)
                             .arg(m_run.result.speedUnit)
                             .arg(m_limits.maxSpeed));
                    return;
                }
                if (m_limits.maxCurrent > 0 && std::abs(s.current) > m_limits.maxCurrent) {
                    fail(tr("current %1 A beyond the test's limit %2 A: stopped at once")
                             .arg(s.current)
                             .arg(m_limits.maxCurrent));
                    return;
                }
                if (m_run.cancelled) {
                    fail(tr("cancelled"));
                    return;
                }
            }
            then(s);
        }));
}

void TuningDrive::cancel()
{
    if (isRunning() && !exiting())
        m_run.cancelled = true;
}

void TuningDrive::fail(const QString& error, bool aborted)
{
    if (!isRunning() || exiting())
        return;
    qCDebug(lcModel) << "tuning test ends:" << error;
    m_run.result.ok = false;
    m_run.result.error = error;
    m_run.result.aborted = aborted;
    finish();
}

// The one exit of every end: the motor stopped and the stop confirmed when it may turn, then
// what the test changed put back, then the report.
void TuningDrive::finish()
{
    if (m_states->motionMayBeOn())
        m_states->go(StopMotor);
    else
        restoreOrReport(false);
}

void TuningDrive::stopMotor()
{
    emit phase(tr("Stopping the motor"));
    writeNumber(m_spec.command, 0, [this](bool sent) {
        m_run.stopSent = sent;
        m_run.stopUntilMs = nowMs() + m_limits.stopTimeoutMs;
        waitStopped();
    });
}

void TuningDrive::waitStopped()
{
    poll(
        [this](const TuningSample& s) {
            if (std::abs(s.speed) <= 0.5 * m_run.closedScale || std::abs(s.speed) < 1e-9) {
                stopped(true);
                return;
            }
            if (nowMs() > m_run.stopUntilMs) {
                stopped(false);
                return;
            }
            // On a test's clock time moves with the line alone: waiting would only slow the test.
            m_states->after(m_clock ? 0 : 20, [this] { waitStopped(); });
        },
        [this] { stopped(false); });
}

void TuningDrive::stopped(bool atRest)
{
    Result& r = m_run.result;
    r.stopConfirmed = m_run.stopSent && atRest;
    if (r.stopConfirmed)
        m_states->stopConfirmed();
    r.stopDetail = r.stopConfirmed ? tr("motor stopped (confirmed)")
                                   : tr("the motor could not be confirmed stopped: check it");
    emit phase(r.stopDetail);
    restoreOrReport(false);
}

void TuningDrive::restoreOrReport(bool modeRestored)
{
    m_states->go(!modeRestored && m_run.modeChanged ? RestoreMode
                 : m_run.commLossChanged            ? RestoreCommLoss
                                                    : Reported);
}

void TuningDrive::report()
{
    // Ended before `done` runs: it may start the next test.
    m_states->end();
    const Done done = std::exchange(m_done, nullptr);
    const Result result = std::exchange(m_run, Run()).result;
    if (done)
        done(result);
}

} // namespace opentop
