#include "model/eol/StationAlarmReset.h"

#include "model/ModelLog.h"
#include "model/alarms/AlarmHistory.h"
#include "model/profile/ProfileRegistry.h"
#include "model/session/DeviceSession.h"
#include "transport/ModbusClient.h"

#include <QTimer>

namespace opentop {

StationAlarmReset::StationAlarmReset(ModbusClient* client, const ProfileRegistry& registry,
                                     const Recipe& recipe, QObject* parent)
    : QObject(parent)
    , m_client(client)
    , m_registry(registry)
    , m_recipe(recipe)
{
}

void StationAlarmReset::reset(const QVector<int>& machineNumbers, Done done)
{
    m_done = std::move(done);
    m_left = machineNumbers;
    m_results.clear();
    QTimer::singleShot(0, this, [this] { next(); });
}

bool StationAlarmReset::allCleared(const QVector<Result>& results)
{
    for (const Result& r : results)
        if (!r.cleared)
            return false;
    return !results.isEmpty();
}

void StationAlarmReset::next()
{
    if (m_session) {
        m_session->deleteLater();
        m_session = nullptr;
    }
    if (m_left.isEmpty()) {
        if (Done done = std::exchange(m_done, nullptr))
            done(m_results);
        return;
    }
    const int slave = m_left.takeFirst();
    Result result;
    result.machineNumber = slave;
    const RecipePosition* position = m_recipe.position(slave);
    const Profile* profile = position ? m_registry.family(position->family) : nullptr;
    if (!m_client || !profile) {
        result.text = !m_client
                          ? tr("machine number %1: not connected to a bus").arg(slave)
                          : tr("machine number %1 is not a position of the recipe").arg(slave);
        m_results << result;
        next();
        return;
    }
    m_session = new DeviceSession(m_client, *profile, slave, position->variants.value(0), this);
    auto* history = new AlarmHistory(m_session, m_session);
    if (!history->canReset()) {
        result.text = tr("machine number %1: %2 drives have no alarm reset command; switch the "
                         "drive off and on")
                          .arg(slave)
                          .arg(profile->name);
        m_results << result;
        next();
        return;
    }
    history->reset([this, result](const AlarmHistory::ResetOutcome& o) mutable {
        result.cleared = o.ok && !o.stillActive.value_or(true);
        result.text = tr("machine number %1: %2").arg(result.machineNumber).arg(o.explanation);
        qCInfo(lcModel) << "station alarm reset" << result.machineNumber << result.cleared
                        << o.explanation;
        m_results << result;
        // Not inside the session's own callback: the session is deleted by next().
        QTimer::singleShot(0, this, [this] { next(); });
    });
}

} // namespace opentop
