#include "profile/ProfileRegistry.h"

#include "ModelLog.h"
#include "profile/ProfileLoader.h"

#include <QDir>
#include <QFile>
#include <cstdio>
#include <cstdlib>

namespace opentop {

ProfileRegistry::ProfileRegistry(QVector<Profile> profiles)
    : m_profiles(std::move(profiles))
{
}

const ProfileRegistry& ProfileRegistry::builtIn()
{
    static const ProfileRegistry registry = [] {
        QVector<Profile> profiles;
        const QDir dir(QStringLiteral(":/profiles"));
        const QStringList files =
            dir.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name);
        for (const QString& file : files) {
            QString error;
            std::optional<Profile> p = ProfileLoader::loadFile(dir.filePath(file), &error);
            if (!p) {
                // A broken built-in profile is a build defect: refuse to run rather than
                // talk to drives with wrong register maps.
                std::fprintf(stderr, "opentop: built-in profile rejected: %s\n", qPrintable(error));
                std::abort();
            }
            profiles << *p;
        }
        if (profiles.isEmpty())
            qCCritical(lcModel) << "no built-in device profiles found";
        return ProfileRegistry(profiles);
    }();
    return registry;
}

const Profile* ProfileRegistry::family(const QString& family) const
{
    for (const Profile& p : m_profiles) {
        if (p.family == family)
            return &p;
    }
    return nullptr;
}

const Profile* ProfileRegistry::forDeviceType(const QString& type, QString* variant) const
{
    const QString wanted = type.trimmed().toLower();
    for (const Profile& p : m_profiles) {
        if (p.family == wanted) {
            if (variant)
                variant->clear();
            return &p;
        }
        for (const ProfileVariant& v : p.variants) {
            if (v.id == wanted) {
                if (variant)
                    *variant = v.id;
                return &p;
            }
        }
    }
    return nullptr;
}

QStringList ProfileRegistry::families() const
{
    QStringList result;
    for (const Profile& p : m_profiles)
        result << p.family;
    return result;
}

QStringList ProfileRegistry::deviceTypes() const
{
    QStringList result;
    for (const Profile& p : m_profiles) {
        if (p.variants.isEmpty())
            result << p.family;
        for (const ProfileVariant& v : p.variants)
            result << v.id;
    }
    return result;
}

} // namespace opentop
