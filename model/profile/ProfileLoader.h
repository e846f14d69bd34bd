#pragma once

#include "model/profile/Profile.h"

#include <QByteArray>
#include <QString>
#include <optional>

namespace opentop {

// Reads a profile from JSON and validates it all (ProfileCrossCheck: what needs every parameter);
// a bad one is refused naming file and entry.
class ProfileLoader
{
public:
    static std::optional<Profile> loadFile(const QString& path, QString* error);
    static std::optional<Profile> loadJson(const QByteArray& json, const QString& sourceName,
                                           QString* error);
};

} // namespace opentop
