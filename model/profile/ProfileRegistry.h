#pragma once

#include "model/profile/Profile.h"

#include <QStringList>
#include <QVector>
#include <optional>

namespace opentop {

// The device profiles compiled into the program (Qt resource :/profiles/*.json).
class ProfileRegistry
{
public:
    // Loads every built-in profile once, in the language of setLanguage(); aborts loudly if a
    // profile or its translation is malformed (a build defect).
    static const ProfileRegistry& builtIn();
    // The language of the profiles' texts for people ("ko", "zh_TW"; "en" or empty: English).
    // Call it before the first builtIn(); later calls are refused (returns false), because
    // callers keep pointers into the registry. A family without a translation stays English.
    static bool setLanguage(const QString& language);
    static QString language();
    // The built-in profiles in `language`, independent of builtIn(): for tests and tools.
    // Empty with *error set when a profile or an existing translation is malformed. The folders
    // are for tests: profiles `<profileDir>/*.json`, texts `<translationDir>/<family>.<lang>.json`.
    static std::optional<ProfileRegistry>
    load(const QString& language, QString* error,
         const QString& profileDir = QStringLiteral(":/profiles"),
         const QString& translationDir = QStringLiteral(":/profiles/i18n"));

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
