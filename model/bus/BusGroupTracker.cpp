#include "model/bus/BusGroupTracker.h"

#include "model/bus/BusDrives.h"
#include "model/session/DeviceParameters.h"
#include "model/session/DeviceSession.h"

#include <memory>

namespace opentop {

BusGroupTracker::BusGroupTracker(BusDrives* drives)
    : GroupReach(drives)
    , m_drives(drives)
{
    connect(drives, &BusDrives::driveAdded, this, &BusGroupTracker::track);
    connect(drives, &BusDrives::driveChanged, this, &BusGroupTracker::track);
    connect(drives, &BusDrives::driveRemoved, this, [this](int slave) {
        m_groups.removeDrive(slave);
        m_attached.remove(slave);
        m_unread.remove(slave);
        emit groupsChanged();
    });
    // Questions name the drives a frame reaches by their machines' names too.
    m_groups.setNames(drives->names());
    connect(drives, &BusDrives::nameChanged, this, [this] {
        m_groups.setNames(m_drives->names());
        emit groupsChanged();
    });
    for (int slave : drives->slaves())
        track(slave);
}

BusGroupTracker* BusGroupTracker::of(const QObject* object)
{
    const QObject* drives = object ? object->parent() : nullptr;
    return drives ? drives->findChild<BusGroupTracker*>(QString(), Qt::FindDirectChildrenOnly)
                  : nullptr;
}

QVector<DeviceSession*> BusGroupTracker::reachedBy(int slave) const
{
    QVector<DeviceSession*> sessions;
    for (int child : m_groups.childrenOf(slave))
        if (DeviceSession* s = m_drives->session(child))
            sessions << s;
    return sessions;
}

QString BusGroupTracker::groupParameterOf(int slave) const
{
    const DeviceSession* session = m_drives->session(slave);
    return session ? BusGroups::groupParameter(session->profile()) : QString();
}

void BusGroupTracker::track(int slave)
{
    const DeviceInfo info = m_drives->info(slave);
    if (info.state != DeviceInfo::State::Present) {
        if (m_groups.contains(slave)) {
            m_groups.removeDrive(slave);
            m_unread.remove(slave);
            emit groupsChanged();
        }
        return;
    }
    const bool added = !m_groups.contains(slave);
    m_groups.addDrive(slave);
    DeviceSession* session = m_drives->session(slave);
    if (!session || m_attached.contains(slave)) {
        if (added)
            emit groupsChanged();
        return;
    }
    m_attached.insert(slave);
    session->setGroupReach(this);
    connect(session, &DeviceSession::written, this,
            [this, slave](const QString& name) { onWritten(slave, name); });
    const QString parameter = BusGroups::groupParameter(session->profile());
    if (parameter.isEmpty()) {
        emit groupsChanged();
        return;
    }
    connect(session, &DeviceSession::valueUpdated, this,
            [this, slave, parameter](const QString& name, const ParamValue& value) {
                if (name != parameter || !value.valid)
                    return;
                const std::optional<int> before = m_groups.groupOf(slave);
                const bool wasUnread = m_unread.remove(slave);
                m_groups.setGroupRaw(slave, qint64(value.raw));
                if (wasUnread || before != m_groups.groupOf(slave))
                    emit groupsChanged();
            });
    m_unread.insert(slave);
    session->read(parameter, [](const DeviceSession::Outcome&) {});
    emit groupsChanged();
}

void BusGroupTracker::readAll(std::function<void(int failed)> done)
{
    auto pending = std::make_shared<int>(1);
    auto failed = std::make_shared<int>(0);
    auto finish = [pending, failed, done] {
        if (--*pending == 0 && done)
            done(*failed);
    };
    for (int slave : m_groups.drives()) {
        DeviceSession* session = m_drives->session(slave);
        const QString parameter = groupParameterOf(slave);
        if (!session || parameter.isEmpty())
            continue;
        ++*pending;
        session->read(parameter, [failed, finish](const DeviceSession::Outcome& o) {
            if (!o.ok)
                ++*failed;
            finish();
        });
    }
    finish();
}

void BusGroupTracker::onWritten(int parent, const QString& name)
{
    const QVector<int> children = m_groups.childrenOf(parent);
    // A setting is read back from the children by the write itself (ReachedDrives).
    const DeviceSession* session = m_drives->session(parent);
    const ParameterMeta* meta = session ? session->profile().parameter(name) : nullptr;
    if (children.isEmpty() || (meta && meta->isReadable()))
        return;
    auto pending = std::make_shared<int>(1);
    auto finish = [this, pending, parent, children, name] {
        if (--*pending == 0)
            emit childrenReread(parent, children, {name});
    };
    for (int child : children) {
        DeviceParameters* parameters = m_drives->parameters(child);
        if (!parameters)
            continue;
        // A command (not readable, e.g. an initialisation or a start): every value of the child
        // known so far, since any of them may have changed.
        QStringList names;
        for (const ParameterMeta& m : parameters->profile().parameters) {
            const DeviceParameters::Entry* e = parameters->entry(m.name);
            if (e && e->device.valid && m.isReadable())
                names << m.name;
        }
        if (names.isEmpty())
            continue;
        ++*pending;
        parameters->refresh(names, [finish](int) { finish(); });
    }
    finish();
}

} // namespace opentop
