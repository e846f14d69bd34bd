#include "model/session/MissingValues.h"

#include "model/profile/Profile.h"
#include "model/session/DeviceSession.h"

namespace opentop {

void MissingValues::readControlling(const ParameterMeta& meta,
                                    std::function<void(QString)> then) const
{
    for (const QString& controlling : meta.controllingParameters()) {
        if (m_session->hasCached(controlling))
            continue;
        // Read what the allowed values depend on first, then try again.
        DeviceSession* session = m_session;
        session->read(controlling, [session, &meta, then](const DeviceSession::Outcome& o) {
            if (!o.ok) {
                then(tr("cannot check the value: reading %1 failed: %2")
                         .arg(session->nameFor(o.parameter), o.error));
                return;
            }
            MissingValues(session).readControlling(meta, then);
        });
        return;
    }
    then(QString());
}

void MissingValues::read(QStringList names, std::function<void(QString)> then) const
{
    while (!names.isEmpty() && m_session->hasCached(names.first()))
        names.removeFirst();
    if (names.isEmpty()) {
        then(QString());
        return;
    }
    const QString name = names.takeFirst();
    DeviceSession* session = m_session;
    session->read(name, [session, names, then](const DeviceSession::Outcome& o) {
        if (!o.ok && !session->hasCached(o.parameter)) {
            then(tr("reading %1 failed: %2").arg(session->nameFor(o.parameter), o.error));
            return;
        }
        MissingValues(session).read(names, then);
    });
}

} // namespace opentop
