#pragma once

#include "model/profile/Profile.h"

#include <QByteArray>
#include <QMap>
#include <QString>
#include <optional>

namespace opentop {

// A profile's texts in another language (model/profiles/i18n/<family>.<lang>.json), validated
// against the profile it is for: format, family, language, exactly the profile's keys
// (ProfileTexts), and the same panel codes and placeholders as the English.
class ProfileTranslation
{
public:
    static constexpr qint64 kMaxFileBytes = 4 * 1024 * 1024;
    static constexpr int kFormatVersion = 1;
    static QString formatName(); // "opentop-profile-translation"

    // `language` is the language the file must declare ("ko"); errors name the file and key.
    static std::optional<ProfileTranslation> loadFile(const QString& path, const Profile& profile,
                                                      const QString& language, QString* error);
    static std::optional<ProfileTranslation> loadJson(const QByteArray& json,
                                                      const QString& sourceName,
                                                      const Profile& profile,
                                                      const QString& language, QString* error);

    QString family() const { return m_family; }
    QString language() const { return m_language; }
    const QMap<QString, QString>& texts() const { return m_texts; }

    // Replaces the profile's texts for people with the translation. What is an interface stays:
    // parameter names, panel codes, EnumOption::canonicalLabel, ValueSpec::canonicalUnit.
    void apply(Profile& profile) const;

private:
    QString m_family;
    QString m_language;
    QMap<QString, QString> m_texts;
};

} // namespace opentop
