#pragma once

#include <QCoreApplication>
#include <QJsonObject>
#include <QStringList>
#include <optional>

namespace opentop {

class Profile;
struct ParameterMeta;

// How a drive that does not report its variant proves it on the bus without moving its motor:
// the profile's "variantProbe" (data, one per family that needs one). A setting whose allowed
// range differs per variant is written once with `value`: the variants whose own range holds
// it accept it, the others refuse it with the device error `refusedCode`. The original value
// is written back and verified after an accepted probe (VariantProber runs it). Which variants
// accept is not written in the data twice: it comes from the parameter's own per-variant
// ranges, so the probe and the validation can never disagree.
class VariantProbe
{
    Q_DECLARE_TR_FUNCTIONS(opentop::VariantProbe)
public:
    QString parameter;     // a setting, never a command or a motion role's register
    double value = 0;      // engineering units
    int refusedCode = -1;  // the device error code of a refusal (the DBU's E8h = 232)
    QStringList accepting; // variants whose range holds `value`
    QStringList refusing;  // the others

    // The profile's probe, or none (no "variantProbe" section).
    static std::optional<VariantProbe> of(const Profile& profile);
    // Reads and checks `section` against `profile` (its parameters and roles already read):
    // an empty string when it is sound or absent.
    static QString check(const Profile& profile, const QJsonObject& section);

    // The probe in words: "Speed lower limit = 280 r/min".
    QString describe(const Profile& profile) const;

private:
    static std::optional<VariantProbe> read(const Profile& profile, const QJsonObject& section,
                                            QString* error);
};

} // namespace opentop
