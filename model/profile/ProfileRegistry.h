#pragma once

#include "profile/Profile.h"

#include <QStringList>
#include <QVector>

namespace opentop {

// The device profiles compiled into the program (Qt resource :/profiles/*.json).
class ProfileRegistry
{
public:
    // Loads every built-in profile once; aborts loudly if one is malformed (a build defect).
    static const ProfileRegistry& builtIn();

    explicit ProfileRegistry(QVector<Profile> profiles);

    const Profile* family(const QString& family) const;
    // Resolves a variant or family id ("dbu200", "dbu", "dcpid") to its profile.
    const Profile* forDeviceType(const QString& type, QString* variant = nullptr) const;
    QStringList families() const;
    QStringList deviceTypes() const; // every family and variant id
    const QVector<Profile>& profiles() const { return m_profiles; }

private:
    QVector<Profile> m_profiles;
};

} // namespace opentop
