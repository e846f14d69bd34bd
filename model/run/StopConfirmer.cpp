#include "model/run/StopConfirmer.h"

#include "model/profile/RoleEvaluator.h"
#include "model/profile/ValueCodec.h"
#include "model/session/DeviceSession.h"

#include <cmath>

namespace opentop {

namespace {

const QString kRunning = QStringLiteral("running");
const QString kCurrentSpeed = QStringLiteral("currentSpeed");
const QString kPriority = QStringLiteral("motionPriority");
const QString kSelected = QStringLiteral("selected");

} // namespace

StopConfirmer::StopConfirmer(DeviceSession* session, const QElapsedTimer& sinceStop,
                             const Timing& timing, QObject* parent)
    : QObject(parent)
    , m_session(session)
    , m_sinceStop(sinceStop)
    , m_timing(timing)
{
    m_timer.setSingleShot(true);
    connect(&m_timer, &QTimer::timeout, this, &StopConfirmer::round);
    m_result.slave = session->slave();
    m_result.family = session->profile().family;
}

QStringList StopConfirmer::decelParameters() const
{
    // Role "decelerations": the settings (in s) that bound how long stopping may take.
    const ProfileRole* role = m_session->profile().role(QStringLiteral("decelerations"));
    return role ? role->parameters : QStringList();
}

std::optional<double>
StopConfirmer::knobSeconds(const std::function<std::optional<double>(const QString&)>& raw) const
{
    const Profile& profile = m_session->profile();
    if (profile.decelerationKnobs.isEmpty())
        return std::nullopt;
    const ProfileRole* role = profile.role(kSelected);
    const ParameterMeta* meta = RoleEvaluator::parameter(profile, kSelected);
    const std::optional<double> value = meta ? raw(meta->name) : std::nullopt;
    if (!value) {
        // Which running data runs is not known: it may be one whose knob cannot be read.
        double most = 0;
        for (const DecelerationKnob& k : profile.decelerationKnobs)
            most = std::max(most, k.maxSeconds);
        return most;
    }
    qint64 selected = qint64(*value);
    if (const BitField* field =
            role->field.isEmpty() ? nullptr : RoleEvaluator::bitField(*meta, role->field))
        selected = RoleEvaluator::fieldValue(*field, *value);
    return profile.knobDeceleration(selected);
}

void StopConfirmer::start(std::function<void(const StopResult&)> done)
{
    m_done = std::move(done);
    round();
}

void StopConfirmer::round()
{
    const Profile& profile = m_session->profile();
    QStringList names;
    for (const QString& role : {kRunning, kCurrentSpeed}) {
        const ParameterMeta* meta = RoleEvaluator::parameter(profile, role);
        if (meta && meta->isReadable() && !names.contains(meta->name))
            names << meta->name;
    }
    if (names.isEmpty()) {
        finish(StopResult::State::NoAnswer,
               tr("%1 drives report neither running state nor speed").arg(profile.family));
        return;
    }
    if (m_first) {
        // Once: how long the drive may take, and whether it takes bus commands at all.
        names += decelParameters();
        if (const ParameterMeta* p = RoleEvaluator::parameter(profile, kPriority))
            names << p->name;
        // A knob's deceleration cannot be read: which running data runs says whether it counts.
        if (const ParameterMeta* p = RoleEvaluator::parameter(profile, kSelected);
            p && p->isReadable() && !profile.decelerationKnobs.isEmpty() &&
            !names.contains(p->name))
            names << p->name;
    }
    m_session->readMany(names, [this](const DeviceSession::ReadManyOutcome& o) {
        const Profile& prof = m_session->profile();
        auto raw = [&o](const QString& n) -> std::optional<double> {
            const DeviceSession::Outcome r = o.results.value(n);
            return r.value.valid ? std::optional<double>(r.value.raw) : std::nullopt;
        };
        if (m_first) {
            m_first = false;
            double decelSeconds = -1;
            for (const QString& n : decelParameters()) {
                const DeviceSession::Outcome r = o.results.value(n);
                if (r.value.valid)
                    decelSeconds = std::max(decelSeconds, r.value.number);
            }
            const ParameterMeta* priority = RoleEvaluator::parameter(prof, kPriority);
            if (priority && RoleEvaluator::holds(prof, kPriority, raw) == false)
                m_priorityNote =
                    tr("%1 is %2: the drive does not take motion commands over the bus (it follows "
                       "its input terminals)")
                        .arg(priority->label,
                             ValueCodec::format(*priority, o.results.value(priority->name).value,
                                                m_session->context()));
            const auto deadline = [this](double seconds) {
                const double ms = seconds >= 0 ? seconds * 1000 * m_timing.decelFactor
                                               : double(m_timing.unknownDecelMs);
                return std::min<qint64>(m_timing.maxMs, qint64(std::ceil(ms)) + m_timing.marginMs);
            };
            m_settingsMs = deadline(decelSeconds);
            // The knob bounds a stop the drive executes; one that does not take bus commands
            // ignored ours, and waiting for its knob would only delay saying so.
            if (m_priorityNote.isEmpty()) {
                if (const std::optional<double> knob = knobSeconds(raw))
                    decelSeconds = std::max(decelSeconds, *knob);
            }
            m_expectedMs = deadline(decelSeconds);
        }
        const std::optional<bool> running = RoleEvaluator::flag(prof, kRunning, raw);
        std::optional<double> speed;
        QString speedText;
        if (const ParameterMeta* s = RoleEvaluator::parameter(prof, kCurrentSpeed)) {
            const DeviceSession::Outcome r = o.results.value(s->name);
            if (r.value.valid) {
                speed = std::abs(r.value.number);
                speedText = ValueCodec::format(*s, r.value, m_session->context());
            }
        }
        QStringList errors;
        for (const QString& n : o.order) {
            if (!o.results.value(n).ok && !o.results.value(n).value.valid)
                errors << o.results.value(n).error;
        }
        errors.removeDuplicates();
        evaluate(running.has_value() || speed.has_value(), running, speed, speedText,
                 errors.join(QStringLiteral("; ")));
    });
}

void StopConfirmer::evaluate(bool readOk, std::optional<bool> running, std::optional<double> speed,
                             const QString& speedText, const QString& error)
{
    const qint64 now = m_sinceStop.elapsed();
    m_result.elapsedMs = now;
    if (!readOk) {
        if (++m_failures >= m_timing.maxFailedReads) {
            finish(StopResult::State::NoAnswer, error);
            return;
        }
    } else {
        m_failures = 0;
        m_result.speed = speed;
        m_result.speedText = speedText;
        // Both, where the drive reports both: a DC controller's output is off at once when it
        // brakes, while the shaft still turns.
        const bool stopped = (!running || !*running) && (!speed || *speed == 0);
        if (stopped) {
            finish(StopResult::State::Stopped, QString());
            return;
        }
        if (speed && m_lowest && *speed < *m_lowest)
            m_fell = true;
        if (speed && (!m_lowest || *speed < *m_lowest)) {
            m_lowest = speed;
            m_progressMs = now;
        }
        const bool slowingDown = speed && now - m_progressMs < m_timing.stallMs;
        // The knob's time is for a drive that slows down: one whose speed has not fallen at all
        // since the stop is judged by its settings' deadline.
        const bool neverSlowed = speed && !m_fell && now >= m_settingsMs;
        if (now >= m_timing.maxMs || ((now >= m_expectedMs || neverSlowed) && !slowingDown)) {
            QString detail =
                speed
                    ? tr("still at %1 after %2 s")
                          .arg(speedText, ValueCodec::formatNumber(now / 1000.0, 1))
                    : tr("still running after %1 s").arg(ValueCodec::formatNumber(now / 1000.0, 1));
            if (!m_priorityNote.isEmpty())
                detail += QStringLiteral("; ") + m_priorityNote;
            finish(StopResult::State::StillRunning, detail);
            return;
        }
    }
    m_timer.start(m_timing.pollMs);
}

void StopConfirmer::finish(StopResult::State state, const QString& detail)
{
    m_timer.stop();
    m_result.state = state;
    m_result.detail = detail;
    m_result.elapsedMs = m_sinceStop.elapsed();
    if (m_done) {
        auto done = std::move(m_done);
        m_done = nullptr;
        done(m_result);
    }
}

} // namespace opentop
