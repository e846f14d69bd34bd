#include "model/station/LatchedAlarms.h"

#include "transport/ModbusClient.h"

namespace opentop {

LatchedAlarms::LatchedAlarms(const ProfileRegistry& registry, QObject* parent)
    : QObject(parent)
    , m_registry(registry)
{
}

void LatchedAlarms::reset(ModbusClient* client, const Recipe& recipe, std::function<void()> cleared)
{
    if (m_latched.isEmpty() || m_reset)
        return;
    m_reset = new StationAlarmReset(client, m_registry, recipe, this);
    emit resetStarted(m_latched);
    m_reset->reset(m_latched, [this, cleared = std::move(cleared)](
                                  const QVector<StationAlarmReset::Result>& results) {
        m_reset->deleteLater();
        m_reset = nullptr;
        QStringList texts;
        for (const StationAlarmReset::Result& r : results)
            texts << r.text;
        const bool all = StationAlarmReset::allCleared(results);
        if (all)
            m_latched.clear();
        emit resetFinished(all, texts);
        if (all && cleared)
            cleared();
    });
}

} // namespace opentop
