#include "model/profile/ProfileTranslation.h"
#include "model/io/InputFile.h"

#include "model/profile/ProfileTexts.h"
#include "model/profile/SettingReference.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QSet>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::ProfileTranslation", text);
}

// Panel codes as a drive shows them (AL001, AL00B, WR017, E01): translators keep them as is.
QStringList panelCodes(const QString& text)
{
    static const QRegularExpression re(
        QStringLiteral("(?<![A-Za-z0-9])(?:(?:AL|WR)[0-9A-F]{3}|E[0-9]{2})(?![A-Za-z0-9])"));
    QStringList found;
    for (auto it = re.globalMatch(text); it.hasNext();)
        found << it.next().captured();
    found.sort();
    found.removeDuplicates(); // a translation may name a code twice
    return found;
}

// Qt (%1, %n) and printf-style (%s, %d, %.1f) placeholders. A percent sign before a space or a
// letter other than a conversion is text ("Load rate %").
QStringList placeholders(const QString& text)
{
    static const QRegularExpression re(
        QStringLiteral("%(?:[0-9]+|n|[-+#0]*[0-9]*(?:\\.[0-9]+)?(?:ll|l|hh|h)?[sdiufxXcgeEp])"));
    QStringList found;
    for (auto it = re.globalMatch(text); it.hasNext();)
        found << it.next().captured();
    found.sort();
    found.removeDuplicates(); // a translation may name a code twice
    return found;
}

// "a, b, c and 4 more" for an error message that must stay readable.
QString someOf(const QStringList& keys)
{
    const int shown = 3;
    QString text = keys.mid(0, shown).join(QStringLiteral(", "));
    if (keys.size() > shown)
        text += tr(" and %1 more").arg(keys.size() - shown);
    return text;
}

} // namespace

QString ProfileTranslation::formatName()
{
    return QStringLiteral("opentop-profile-translation");
}

std::optional<ProfileTranslation> ProfileTranslation::loadFile(const QString& path,
                                                               const Profile& profile,
                                                               const QString& language,
                                                               QString* error)
{
    QByteArray data;
    const InputFile::Status read = InputFile::read(path, kMaxFileBytes, &data, error);
    if (read == InputFile::Status::CannotOpen)
        return std::nullopt;
    if (read == InputFile::Status::TooLarge) {
        if (error)
            *error = tr("%1 is larger than %2 MB, the most a profile translation may hold")
                         .arg(path)
                         .arg(kMaxFileBytes / (1024 * 1024));
        return std::nullopt;
    }
    return loadJson(data, QFileInfo(path).fileName(), profile, language, error);
}

std::optional<ProfileTranslation>
ProfileTranslation::loadJson(const QByteArray& json, const QString& sourceName,
                             const Profile& profile, const QString& language, QString* error)
{
    auto fail = [&](const QString& message) {
        if (error)
            *error = sourceName + QStringLiteral(": ") + message;
        return std::nullopt;
    };
    if (json.size() > kMaxFileBytes)
        return fail(tr("larger than %1 MB, the most a profile translation may hold")
                        .arg(kMaxFileBytes / (1024 * 1024)));
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError)
        return fail(tr("not valid JSON at offset %1: %2")
                        .arg(parseError.offset)
                        .arg(parseError.errorString()));
    if (!doc.isObject())
        return fail(tr("the top level must be a JSON object"));
    const QJsonObject root = doc.object();
    if (root.value(QStringLiteral("format")).toString() != formatName())
        return fail(tr("\"format\" must be \"%1\"").arg(formatName()));
    const QJsonValue version = root.value(QStringLiteral("formatVersion"));
    if (!version.isDouble() || version.toDouble() != kFormatVersion)
        return fail(tr("\"formatVersion\" must be %1").arg(kFormatVersion));
    ProfileTranslation t;
    t.m_family = root.value(QStringLiteral("family")).toString();
    t.m_language = root.value(QStringLiteral("language")).toString();
    if (t.m_family != profile.family)
        return fail(
            tr("\"family\" is \"%1\", but the profile is \"%2\"").arg(t.m_family, profile.family));
    if (t.m_language.isEmpty() || (!language.isEmpty() && t.m_language != language))
        return fail(tr("\"language\" is \"%1\", expected \"%2\"").arg(t.m_language, language));
    const QJsonValue texts = root.value(QStringLiteral("texts"));
    if (!texts.isObject())
        return fail(tr("\"texts\" must be an object of key → text"));
    const QJsonObject textObject = texts.toObject();
    for (auto it = textObject.begin(); it != textObject.end(); ++it) {
        if (!it.value().isString() || it.value().toString().trimmed().isEmpty())
            return fail(tr("texts \"%1\" must be a non-empty string").arg(it.key()));
        t.m_texts.insert(it.key(), it.value().toString());
    }

    const QMap<QString, QString> english = ProfileTexts::of(profile);
    QStringList missing, unknown;
    for (auto it = english.begin(); it != english.end(); ++it) {
        if (!t.m_texts.contains(it.key()))
            missing << it.key();
    }
    for (auto it = t.m_texts.begin(); it != t.m_texts.end(); ++it) {
        if (!english.contains(it.key()))
            unknown << it.key();
    }
    if (!missing.isEmpty() || !unknown.isEmpty()) {
        QStringList parts;
        if (!missing.isEmpty())
            parts << tr("%1 key(s) of the profile missing: %2")
                         .arg(missing.size())
                         .arg(someOf(missing));
        if (!unknown.isEmpty())
            parts << tr("%1 key(s) the profile does not have: %2")
                         .arg(unknown.size())
                         .arg(someOf(unknown));
        return fail(parts.join(QStringLiteral("; ")));
    }
    for (auto it = english.begin(); it != english.end(); ++it) {
        const QString& translated = t.m_texts.value(it.key());
        if (panelCodes(translated) != panelCodes(it.value()))
            return fail(tr("texts \"%1\": the panel codes must stay as in the English (%2), "
                           "found (%3)")
                            .arg(it.key(), panelCodes(it.value()).join(QStringLiteral(", ")),
                                 panelCodes(translated).join(QStringLiteral(", "))));
        if (placeholders(translated) != placeholders(it.value()))
            return fail(tr("texts \"%1\": the placeholders must stay as in the English (%2), "
                           "found (%3)")
                            .arg(it.key(), placeholders(it.value()).join(QStringLiteral(", ")),
                                 placeholders(translated).join(QStringLiteral(", "))));
        // A setting named by reference is shown by its label in the language: the reference
        // itself must stay (SettingReference).
        if (SettingReference::names(translated) != SettingReference::names(it.value()))
            return fail(tr("texts \"%1\": the settings named ({setting:…}) must stay as in the "
                           "English (%2), found (%3)")
                            .arg(it.key(),
                                 SettingReference::names(it.value()).join(QStringLiteral(", ")),
                                 SettingReference::names(translated).join(QStringLiteral(", "))));
    }
    return t;
}

void ProfileTranslation::apply(Profile& profile) const
{
    if (profile.family != m_family)
        return;
    ProfileTexts::forEachText(profile, [&](const QString& key, QString& text) {
        const auto it = m_texts.constFind(key);
        if (it != m_texts.constEnd() && !text.trimmed().isEmpty())
            text = *it;
    });
}

} // namespace opentop
