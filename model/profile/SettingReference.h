#pragma once

#include <QString>
#include <QStringList>

namespace opentop {

class Profile;

// A profile text that names a setting writes "{setting:alarm.overload_time}", not a register
// address: people look for a setting by the name the program shows, on the page it is on. The
// loader checks that every reference names a parameter of the profile, a translation must keep
// the English's references, and the registry resolves them in the language shown:
// "Overload alarm output time (Alarm/warning parameters)", the label and its group's.
class SettingReference
{
public:
    // The parameter names referred to in `text`, sorted, each once.
    static QStringList names(const QString& text);
    // `text` with every reference replaced by its setting as the program shows it; a name the
    // profile lacks stays as written (the loader refuses such a profile).
    static QString resolved(const QString& text, const Profile& profile);
    // "Overload alarm output time (Alarm/warning parameters)"; the name itself when unknown.
    static QString settingText(const Profile& profile, const QString& parameter);
    // Resolves the references of every text of `profile` (after its translation is applied).
    static void resolveAll(Profile& profile);
    // The first reference of the profile's texts to a parameter it lacks, as "key: name";
    // empty when every one is known.
    static QString firstUnknown(const Profile& profile);
};

} // namespace opentop
