#pragma once

#include "model/eol/RecipeTypes.h"
#include "model/eol/UnitRecord.h"
#include "model/session/VariantProber.h"

#include <QCoreApplication>
#include <optional>

namespace opentop {

class Profile;

// Which variant a position's drive is, how that is known, and whether the recipe takes it: a
// drive's own report, else the profile's probe, else a person's word (eol run --variant, the
// recipe's "operator" option), else the recipe's single variant assumed, unless the recipe or
// several allowed variants need proof. A drive of a variant the recipe does not allow never
// passes, and a variant that was not read or proven is never recorded as if it were.
class VariantDecision
{
    Q_DECLARE_TR_FUNCTIONS(opentop::VariantDecision)
public:
    struct Evidence
    {
        QString reported;                           // the drive's identification
        std::optional<VariantProber::Result> probe; // when the probe ran
        QString asserted;     // given for this position by the person running the unit
        QString operatorName; // who runs the unit
    };
    struct Decision
    {
        bool ok = false;
        QString variant;
        VariantSource source = VariantSource::None;
        QString proof;
        QString failure; // an identity error, in words: what was found, what the recipe allows
    };

    static Decision decide(const Profile& profile, const RecipePosition& position,
                           const Evidence& evidence);

private:
    static QString allowedText(const Profile& profile, const RecipePosition& position);
    static QString modelOf(const Profile& profile, const QString& variant);
};

} // namespace opentop
