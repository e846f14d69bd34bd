#include "model/profile/SettingReference.h"

#include "model/profile/Profile.h"
#include "model/profile/ProfileTexts.h"

#include <QRegularExpression>

namespace opentop {

namespace {

const QRegularExpression& pattern()
{
    static const QRegularExpression re(QStringLiteral("\\{setting:([A-Za-z0-9_.]+)\\}"));
    return re;
}

} // namespace

QStringList SettingReference::names(const QString& text)
{
    QStringList found;
    for (auto it = pattern().globalMatch(text); it.hasNext();)
        found << it.next().captured(1);
    found.sort();
    found.removeDuplicates();
    return found;
}

QString SettingReference::settingText(const Profile& profile, const QString& parameter)
{
    const ParameterMeta* meta = profile.parameter(parameter);
    if (!meta)
        return parameter;
    const ProfileGroup* group = profile.group(meta->group);
    return group && !group->label.isEmpty()
               ? QStringLiteral("%1 (%2)").arg(meta->label, group->label)
               : meta->label;
}

QString SettingReference::resolved(const QString& text, const Profile& profile)
{
    if (!text.contains(QLatin1String("{setting:")))
        return text;
    QString out;
    qsizetype last = 0;
    for (auto it = pattern().globalMatch(text); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        out += text.mid(last, m.capturedStart() - last);
        out +=
            profile.parameter(m.captured(1)) ? settingText(profile, m.captured(1)) : m.captured();
        last = m.capturedEnd();
    }
    return out + text.mid(last);
}

void SettingReference::resolveAll(Profile& profile)
{
    // Labels first, as they are now: a resolved text must not depend on the order of visits.
    const Profile labels = profile;
    QHash<QString, QString> written;
    ProfileTexts::forEachText(profile, [&labels, &written](const QString& key, QString& text) {
        if (names(text).isEmpty())
            return;
        written.insert(key, text);
        text = resolved(text, labels);
    });
    profile.referencedTexts.insert(written);
}

QString SettingReference::firstUnknown(const Profile& profile)
{
    const QMap<QString, QString> texts = ProfileTexts::of(profile);
    for (auto it = texts.cbegin(); it != texts.cend(); ++it) {
        for (const QString& name : names(it.value())) {
            if (!profile.parameter(name))
                return QStringLiteral("%1: %2").arg(it.key(), name);
        }
    }
    return QString();
}

} // namespace opentop
