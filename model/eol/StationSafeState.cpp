#include "model/eol/StationSafeState.h"

#include "model/ModelLog.h"
#include "model/profile/ProfileRegistry.h"
#include "model/profile/RoleEvaluator.h"
#include "model/profile/ValueCodec.h"
#include "model/run/RunControl.h"
#include "model/session/DeviceSession.h"

#include <QElapsedTimer>
#include <QTimer>

namespace opentop {

namespace {

const QString kRunning = QStringLiteral("running");
const QString kCurrentSpeed = QStringLiteral("currentSpeed");
const QString kMotionPriority = QStringLiteral("motionPriority");
const QString kIoPriority = QStringLiteral("ioPriority");

} // namespace

bool PositionSafety::blocksUnits() const
{
    const bool leftRunning = running.value_or(false) && busPriority && !stopConfirmed;
    const bool leftInBusControl = stopConfirmed && !problem.isEmpty();
    return leftRunning || leftInBusControl;
}

QString PositionSafety::blockingText(const QVector<PositionSafety>& found)
{
    QStringList lines;
    for (const PositionSafety& p : found)
        if (p.blocksUnits())
            lines << p.summary();
    return lines.join(QStringLiteral("; "));
}

QString PositionSafety::summary() const
{
    // Translated in StationSafeState's context (a plain struct has none of its own).
    if (!answered)
        return QCoreApplication::translate("opentop::StationSafeState",
                                           "%1: no answer (%2); not checked")
            .arg(name, problem);
    QString text;
    if (running.value_or(false)) {
        text = QCoreApplication::translate("opentop::StationSafeState", "%1 was RUNNING (%2)")
                   .arg(name, speedText);
        if (stopConfirmed)
            text += QCoreApplication::translate("opentop::StationSafeState",
                                                ": stopped by the station");
    } else {
        text = QCoreApplication::translate("opentop::StationSafeState", "%1 stopped").arg(name);
    }
    if (priorityGivenBack)
        text += QCoreApplication::translate("opentop::StationSafeState",
                                            "; control given back to its inputs (I/O priority)");
    if (!problem.isEmpty())
        text += QStringLiteral(": ") + problem;
    return text;
}

StationSafeState::StationSafeState(ModbusClient* client, const ProfileRegistry& registry,
                                   const Recipe& recipe, QObject* parent)
    : QObject(parent)
    , m_client(client)
    , m_registry(registry)
    , m_recipe(recipe)
{
}

void StationSafeState::run(Done done)
{
    m_done = std::move(done);
    m_index = -1;
    m_found.clear();
    QTimer::singleShot(0, this, [this] { next(); });
}

void StationSafeState::next()
{
    if (m_session) {
        m_session->deleteLater();
        m_session = nullptr;
    }
    if (++m_index >= m_recipe.positions.size()) {
        Done done = std::move(m_done);
        m_done = nullptr;
        if (done)
            done(m_found);
        return;
    }
    const RecipePosition& position = m_recipe.positions[m_index];
    PositionSafety found;
    found.machineNumber = position.machineNumber;
    found.name = position.name.isEmpty()
                     ? tr("drive %1").arg(position.machineNumber)
                     : tr("drive %1 (%2)").arg(position.machineNumber).arg(position.name);
    m_found.append(found);
    const Profile* profile = m_registry.family(position.family);
    if (!profile) {
        m_found.last().problem = tr("the recipe's family %1 is not known").arg(position.family);
        next();
        return;
    }
    m_session = new DeviceSession(m_client, *profile, position.machineNumber,
                                  position.variants.value(0), this);
    read(m_session);
}

void StationSafeState::read(DeviceSession* session)
{
    const Profile& profile = session->profile();
    QStringList names;
    for (const QString& role : {kRunning, kCurrentSpeed, kMotionPriority}) {
        const ParameterMeta* meta = RoleEvaluator::parameter(profile, role);
        if (meta && meta->isReadable() && !names.contains(meta->name))
            names << meta->name;
    }
    const int index = m_index;
    session->readMany(names, [this, index, session](const DeviceSession::ReadManyOutcome& o) {
        if (index != m_index)
            return;
        PositionSafety* found = &m_found[index];
        const Profile& prof = session->profile();
        auto raw = [&o](const QString& n) -> std::optional<double> {
            const DeviceSession::Outcome r = o.results.value(n);
            return r.value.valid ? std::optional<double>(r.value.raw) : std::nullopt;
        };
        found->running = RoleEvaluator::flag(prof, kRunning, raw);
        found->answered = o.failed < o.order.size();
        if (!found->answered) {
            found->problem = o.results.value(o.order.value(0)).error;
            next();
            return;
        }
        if (const ParameterMeta* s = RoleEvaluator::parameter(prof, kCurrentSpeed)) {
            const DeviceSession::Outcome r = o.results.value(s->name);
            if (r.value.valid)
                found->speedText = ValueCodec::format(*s, r.value, session->context());
        }
        // No such role: the drive always takes bus commands (the DC controller).
        found->busPriority = !RoleEvaluator::parameter(prof, kMotionPriority) ||
                             RoleEvaluator::holds(prof, kMotionPriority, raw).value_or(false);
        if (!found->running.has_value()) {
            found->problem = tr("whether its motor runs cannot be read");
            next();
            return;
        }
        if (!*found->running) {
            found->stopConfirmed = true;
            giveBack(found, session);
            return;
        }
        if (!found->busPriority) {
            // Turning from its own inputs: the machine's, not a test the station left running.
            found->problem = tr("it runs from its input terminals (I/O priority): not the "
                                "station's to stop; stop it at the machine");
            next();
            return;
        }
        stop(found, session);
    });
}

void StationSafeState::stop(PositionSafety* found, DeviceSession* session)
{
    qCWarning(lcModel) << "station: drive" << found->machineNumber
                       << "was left running in communication priority; stopping it";
    auto* control = new RunControl(m_client, m_registry, this);
    const int index = m_index;
    QElapsedTimer sinceStop;
    sinceStop.start();
    control->execute(session, {RunControl::Action::Stop, 0, QString()},
                     [this, control, index, session, sinceStop](const RunControl::Outcome& o) {
                         control->deleteLater();
                         if (index != m_index)
                             return;
                         PositionSafety* f = &m_found[index];
                         f->stopSent = o.sent;
                         if (!o.ok) {
                             f->problem = tr("the stop was refused: %1").arg(o.error);
                             next();
                             return;
                         }
                         auto* confirm = new StopConfirmer(session, sinceStop, m_timing, this);
                         confirm->start([this, confirm, index, session](const StopResult& r) {
                             confirm->deleteLater();
                             if (index != m_index)
                                 return;
                             PositionSafety* c = &m_found[index];
                             c->stopConfirmed = r.state == StopResult::State::Stopped;
                             if (!c->stopConfirmed) {
                                 // Kept in communication priority: its inputs are not handed
                                 // a motor the station could not stop.
                                 c->problem = tr("NOT CONFIRMED STOPPED: %1").arg(r.detail);
                                 next();
                                 return;
                             }
                             giveBack(c, session);
                         });
                     });
}

bool StationSafeState::recipeSetsPriority(const RecipePosition& position,
                                          const DeviceSession& session) const
{
    const ParameterMeta* meta = RoleEvaluator::parameter(session.profile(), kIoPriority);
    if (!meta)
        return false;
    for (const RecipeSetting& s : position.settings)
        if (s.name == meta->name)
            return true;
    return false;
}

void StationSafeState::giveBack(PositionSafety* found, DeviceSession* session)
{
    const Profile& profile = session->profile();
    const ProfileRole* role = profile.role(kIoPriority);
    const ParameterMeta* meta = role ? profile.parameter(role->parameter) : nullptr;
    if (!meta || !role->value || !found->busPriority ||
        recipeSetsPriority(m_recipe.positions[m_index], *session)) {
        next();
        return;
    }
    DeviceSession::WriteOptions options;
    options.explicitCommand = true; // the station's own safety step, named on its screen
    const int index = m_index;
    session->write(meta->name, RoleEvaluator::writeText(*meta, *role->value, session->context()),
                   options, [this, index](const DeviceSession::Outcome& o) {
                       if (index != m_index)
                           return;
                       PositionSafety* f = &m_found[index];
                       f->priorityGivenBack = o.ok;
                       if (!o.ok)
                           f->problem =
                               tr("control could not be given back to its inputs: %1").arg(o.error);
                       next();
                   });
}

} // namespace opentop
