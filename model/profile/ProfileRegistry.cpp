#include "model/profile/ProfileRegistry.h"

#include "model/ModelLog.h"
#include "model/profile/ProfileLoader.h"
#include "model/profile/ProfileTranslation.h"
#include "model/profile/SettingReference.h"

#include <QDir>
#include <QFile>
#include <cstdio>
#include <cstdlib>

namespace opentop {

ProfileRegistry::ProfileRegistry(QVector<Profile> profiles)
    : m_profiles(std::move(profiles))
{
}

namespace {

struct LanguageState
{
    QString language;
    bool builtInMade = false;
};

LanguageState& languageState()
{
    static LanguageState state;
    return state;
}

bool isEnglish(const QString& language)
{
    return language.isEmpty() || language == QLatin1String("en");
}

} // namespace

bool ProfileRegistry::setLanguage(const QString& language)
{
    LanguageState& state = languageState();
    const QString wanted = isEnglish(language) ? QString() : language;
    if (state.builtInMade && wanted != state.language) {
        qCWarning(lcModel) << "profile language" << language
                           << "set after the profiles were loaded; they stay in"
                           << (state.language.isEmpty() ? QStringLiteral("en") : state.language);
        return false;
    }
    state.language = wanted;
    return true;
}

QString ProfileRegistry::language()
{
    return languageState().language.isEmpty() ? QStringLiteral("en") : languageState().language;
}

std::optional<ProfileRegistry> ProfileRegistry::load(const QString& language, QString* error,
                                                     const QString& profileDir,
                                                     const QString& translationDir)
{
    QVector<Profile> profiles;
    const QDir dir(profileDir);
    // Files only: the translations sit in :/profiles/i18n/, which this listing does not enter.
    const QStringList files = dir.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name);
    for (const QString& file : files) {
        std::optional<Profile> p = ProfileLoader::loadFile(dir.filePath(file), error);
        if (!p)
            return std::nullopt;
        if (!isEnglish(language)) {
            const QString path =
                QDir(translationDir)
                    .filePath(QStringLiteral("%1.%2.json").arg(p->family, language));
            if (QFile::exists(path)) {
                const std::optional<ProfileTranslation> t =
                    ProfileTranslation::loadFile(path, *p, language, error);
                if (!t)
                    return std::nullopt;
                t->apply(*p);
            }
        }
        // Settings named in texts, by their labels in the language shown.
        SettingReference::resolveAll(*p);
        profiles << *p;
    }
    return ProfileRegistry(profiles);
}

const ProfileRegistry& ProfileRegistry::builtIn()
{
    static const ProfileRegistry registry = [] {
        languageState().builtInMade = true;
        QString error;
        std::optional<ProfileRegistry> loaded = load(languageState().language, &error);
        if (!loaded) {
            // A broken built-in profile or translation is a build defect: refuse to run rather
            // than talk to drives with wrong register maps or show half-checked texts.
            std::fprintf(stderr, "opentop: built-in profile rejected: %s\n", qPrintable(error));
            std::abort();
        }
        if (loaded->profiles().isEmpty())
            qCCritical(lcModel) << "no built-in device profiles found";
        return *loaded;
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
