#pragma once

#include <QCoreApplication>
#include <QString>
#include <QStringList>
#include <functional>

namespace opentop {

class DeviceSession;
struct ParameterMeta;

// Reads, before a write is checked, the values the check depends on that a session has not
// cached yet: the settings the written one's allowed values depend on, and the settings whose
// allowed values depend on it (DependentValues). One read after the other; nothing is written
// until they are known.
class MissingValues
{
    Q_DECLARE_TR_FUNCTIONS(opentop::MissingValues)
public:
    explicit MissingValues(DeviceSession* session)
        : m_session(session)
    {
    }

    // Reads the controlling parameters of `meta` not cached yet; `then` gets the first failure,
    // or nothing.
    void readControlling(const ParameterMeta& meta, std::function<void(QString)> then) const;
    // Reads those of `names` not cached yet; `then` gets the first failure, or nothing.
    void read(QStringList names, std::function<void(QString)> then) const;

private:
    // The replies come to the session's callbacks: they capture the session, not this object.
    DeviceSession* m_session;
};

} // namespace opentop
