#pragma once

#include "model/profile/Profile.h"

#include <QJsonObject>

namespace opentop {

class JsonReader;

// The checks of a profile that need every parameter read (ProfileLoader runs them once the
// parameters are in): their references to one another (storeWith, a bit field's function, a
// condition's parameter), each default against its allowed values, registers that overlap or
// run past 0xFFFF, and the identify read, read here because the parameters it names must lie
// inside it. The first failure is recorded in the JsonReader, naming the entry.
class ProfileCrossCheck
{
public:
    // False with the error in `json`.
    static bool check(const QJsonObject& root, JsonReader& json, Profile* profile);
    // Whether `raw` is one of the values `spec` allows (any value when it lists none).
    static bool allows(const ValueSpec& spec, double raw);

private:
    static bool checkParameters(JsonReader& json, const Profile* p);
    static bool readIdentify(const QJsonObject& root, JsonReader& json, Profile* p);
};

} // namespace opentop
