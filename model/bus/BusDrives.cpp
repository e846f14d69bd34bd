#include "model/bus/BusDrives.h"

#include "model/bus/DriveName.h"
#include "model/profile/ProfileRegistry.h"
#include "model/session/DeviceParameters.h"
#include "model/session/DeviceSession.h"
#include "model/session/StoreTracker.h"
#include "transport/ModbusClient.h"

#include <algorithm>
#include <memory>

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

BusDrives* BusDrives::of(const QObject* sessionOrParameters)
{
    return sessionOrParameters ? qobject_cast<BusDrives*>(sessionOrParameters->parent()) : nullptr;
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
        StoreTracker::of(d.session);          // from the first write on: what a restore must store
        d.session->setMachineName(m_names.value(info.slave));
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
    m_variantDeclined.remove(slave); // another drive may answer there later
    // Gone from the list first, deleted after the listeners heard it: a page showing the drive
    // lets go of its parameters while they still exist (the bus list's Remove from list).
    const std::unique_ptr<DeviceSession> session(it->session); // deleted last, as it was made
    const std::unique_ptr<DeviceParameters> parameters(it->parameters);
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
    DeviceInfo info = m_drives.value(slave).info;
    info.machineName = m_names.value(slave);
    return info;
}

QString BusDrives::setName(int slave, const QString& name)
{
    const QString problem = DriveName::problem(name);
    if (!problem.isEmpty())
        return problem;
    const QString kept = DriveName::cleaned(name);
    if (kept == m_names.value(slave))
        return QString();
    if (kept.isEmpty())
        m_names.remove(slave);
    else
        m_names.insert(slave, kept);
    if (DeviceSession* s = session(slave))
        s->setMachineName(kept);
    emit nameChanged(slave, kept);
    if (m_drives.contains(slave))
        emit driveChanged(slave);
    return QString();
}

void BusDrives::setNames(const QHash<int, QString>& names)
{
    for (auto it = names.cbegin(); it != names.cend(); ++it) {
        // A remembered name was checked when it was set; one edited by hand is checked again.
        if (DriveName::problem(it.value()).isEmpty() && !it.value().trimmed().isEmpty() &&
            m_names.value(it.key()) != DriveName::cleaned(it.value())) {
            m_names.insert(it.key(), DriveName::cleaned(it.value()));
            if (DeviceSession* s = session(it.key()))
                s->setMachineName(m_names.value(it.key()));
            if (m_drives.contains(it.key()))
                emit driveChanged(it.key());
        }
    }
}

QString BusDrives::label(int slave) const
{
    return DriveName::text(slave, m_names.value(slave));
}

QString BusDrives::listed(int slave) const
{
    return DriveName::listed(slave, m_names.value(slave));
}

QString BusDrives::title(int slave) const
{
    return DriveName::title(slave, m_names.value(slave));
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
    // What is allowed changed with the variant: the edits are checked against it.
    if (it->parameters)
        it->parameters->recheck();
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
