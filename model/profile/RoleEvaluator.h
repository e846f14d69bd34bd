#pragma once

#include "model/profile/Profile.h"
#include "model/profile/ValueContext.h"

#include <QCoreApplication>
#include <functional>
#include <optional>

namespace opentop {

// Evaluates a profile's roles on values read from a drive: whether "running" or "alarmActive"
// hold, the value of a bit field, the text to write for a command role. Keeps generic code
// free of family knowledge (docs/profile-format.md, "Roles").
class RoleEvaluator
{
    Q_DECLARE_TR_FUNCTIONS(opentop::RoleEvaluator)
public:
    // Raw value of a parameter as read, or nothing when not known.
    using RawLookup = std::function<std::optional<double>(const QString& parameter)>;

    // The parameter a single-parameter role names; nullptr when the role or parameter is absent.
    static const ParameterMeta* parameter(const Profile& profile, const QString& role);
    // A flag role ("running", "alarmActive"): its bit field, or any non-zero value.
    static std::optional<bool> flag(const Profile& profile, const QString& role,
                                    const RawLookup& raw);
    // Whether a setting role with a value ("motionPriority") holds that value.
    static std::optional<bool> holds(const Profile& profile, const QString& role,
                                     const RawLookup& raw);

    static const BitField* bitField(const ParameterMeta& meta, const QString& field);
    static qint64 fieldValue(const BitField& field, double raw);
    // The field's label for its value ("Running", "CCW"), or the number.
    static QString fieldText(const BitField& field, qint64 value);

    // What to pass to DeviceSession::write for raw value `raw` of `meta`: the enumeration code
    // when it is one, otherwise the engineering value (raw × scale).
    static QString writeText(const ParameterMeta& meta, qint64 raw, const ValueContext& context);
    // "START (1)", "0 %" — a role's value for people.
    static QString valueText(const ParameterMeta& meta, qint64 raw, const ValueContext& context);
    // "run.start = START (1) (0x2003, function 06)": a write as the user is told about it, the
    // parameter named as `context` names it (its label in the program's windows).
    static QString describeWrite(const ParameterMeta& meta, const QString& valueText,
                                 const ValueContext& context = {});
};

} // namespace opentop
