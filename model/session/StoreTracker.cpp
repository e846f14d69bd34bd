#include "model/session/StoreTracker.h"

#include "model/session/DeviceSession.h"

namespace opentop {

StoreTracker* StoreTracker::of(DeviceSession* session)
{
    if (!session)
        return nullptr;
    if (auto* tracker = session->findChild<StoreTracker*>(QString(), Qt::FindDirectChildrenOnly))
        return tracker;
    return new StoreTracker(session);
}

StoreTracker::StoreTracker(DeviceSession* session)
    : QObject(session)
    , m_session(session)
{
    connect(session, &DeviceSession::written, this, &StoreTracker::written);
}

void StoreTracker::seed(const QStringList& storeCommands)
{
    const QStringList before = m_unstored;
    for (const QString& c : storeCommands) {
        if (!m_unstored.contains(c))
            m_unstored << c;
    }
    if (m_unstored != before)
        emit changed();
}

void StoreTracker::written(const QString& name)
{
    const Profile& profile = m_session->profile();
    const ParameterMeta* meta = profile.parameter(name);
    if (!meta)
        return;
    const QStringList before = m_unstored;
    // A store command writes the group to memory, a reload brings the stored values back:
    // either way what acts now is what is stored.
    m_unstored.removeAll(name);
    if (!meta->storeWith.isEmpty()) {
        if (meta->writeBlock.isSet())
            m_unstored.removeAll(meta->storeWith); // the block frame stores its group
        else if (!m_unstored.contains(meta->storeWith))
            m_unstored << meta->storeWith;
    }
    if (m_unstored != before)
        emit changed();
}

} // namespace opentop
