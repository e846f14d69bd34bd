#include "bus/BusDrives.h"

#include "ModbusClient.h"
#include "profile/ProfileRegistry.h"
#include "session/DeviceParameters.h"
#include "session/DeviceSession.h"

#include <algorithm>

namespace opentop {

BusDrives::BusDrives(ModbusClient* client, const ProfileRegistry& registry, QObject* parent)
    : QObject(parent)
    , m_client(client)
    , m_registry(registry)
{
}

BusDrives::~BusDrives()
{
    clear();
}

void BusDrives::update(const DeviceInfo& info)
{
    const bool added = !m_drives.contains(info.slave);
    Drive& d = m_drives[info.slave];
    const QString family = d.info.family;
    d.info = info;
    if (m_client) {
        if (info.line.isSet())
            m_client->setDriveLine(info.slave, info.line);
        d.info.line =
            m_client->hasOwnLine(info.slave) ? m_client->driveLine(info.slave) : LineFormat();
    }
    if (d.session && family != info.family && info.state == DeviceInfo::State::Present) {
        // Another family now answers at this number: the old session's profile is wrong.
        delete d.parameters;
        delete d.session;
        d.parameters = nullptr;
        d.session = nullptr;
    }
    const Profile* profile = m_registry.family(info.family);
    if (!d.session && info.state == DeviceInfo::State::Present && profile) {
        d.session = new DeviceSession(m_client, *profile, info.slave, info.variant, this);
        d.session->setLabelsInMessages(true); // the program's windows name parameters by label
        d.parameters = new DeviceParameters(d.session, this);
    } else if (d.session && !info.variant.isEmpty()) {
        d.session->setVariant(info.variant);
    }
    emit added ? driveAdded(info.slave) : driveChanged(info.slave);
}

void BusDrives::setLine(int slave, const LineFormat& format)
{
    if (!m_client)
        return;
    m_client->setDriveLine(slave, format);
    const auto it = m_drives.find(slave);
    if (it == m_drives.end())
        return;
    it->info.line = m_client->hasOwnLine(slave) ? m_client->driveLine(slave) : LineFormat();
    emit driveChanged(slave);
}

void BusDrives::remove(int slave)
{
    const auto it = m_drives.find(slave);
    if (it == m_drives.end())
        return;
    delete it->parameters;
    delete it->session;
    m_drives.erase(it);
    emit driveRemoved(slave);
}

void BusDrives::clear()
{
    for (int slave : slaves())
        remove(slave);
}

QVector<int> BusDrives::slaves() const
{
    QVector<int> result;
    for (auto it = m_drives.cbegin(); it != m_drives.cend(); ++it)
        result << it.key();
    std::sort(result.begin(), result.end());
    return result;
}

DeviceInfo BusDrives::info(int slave) const
{
    return m_drives.value(slave).info;
}

DeviceSession* BusDrives::session(int slave) const
{
    return m_drives.value(slave).session;
}

DeviceParameters* BusDrives::parameters(int slave) const
{
    return m_drives.value(slave).parameters;
}

void BusDrives::setVariant(int slave, const QString& variant)
{
    auto it = m_drives.find(slave);
    if (it == m_drives.end())
        return;
    it->info.variant = variant;
    if (const Profile* p = m_registry.family(it->info.family)) {
        if (const ProfileVariant* v = p->variant(variant))
            it->info.model = v->model;
    }
    if (it->session)
        it->session->setVariant(variant);
    emit driveChanged(slave);
}

void BusDrives::setLinkUp(bool up)
{
    if (up == m_linkUp)
        return;
    m_linkUp = up;
    emit linkChanged(up);
}

} // namespace opentop
