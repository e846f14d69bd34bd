#pragma once

#include "model/profile/Profile.h"

#include <QMap>
#include <QString>
#include <functional>

namespace opentop {

// Every translatable text of a profile by a stable key: the C++ port of
// translations/profiles/extract.py (same keys, same texts), which translation files are keyed by.
class ProfileTexts
{
public:
    // Key → text of every non-blank text, as extract.py gives it for the profile's JSON (a text
    // that names settings as written, with its {setting:…} references).
    static QMap<QString, QString> of(const Profile& profile);

    // Calls `visit(key, text)` for every text field of `profile`, so that a translation can
    // replace it in place. Also visits the texts a `when` condition inherits from its parameter
    // (a copy of the parameter's unit, note and enumeration), under the parameter's key.
    static void forEachText(Profile& profile,
                            const std::function<void(const QString& key, QString& text)>& visit);

private:
    static void visitTexts(Profile& profile, bool inherited,
                           const std::function<void(const QString& key, QString& text)>& visit);
};

} // namespace opentop
