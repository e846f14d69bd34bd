#pragma once

#include "model/eol/RecipeTypes.h"
#include "model/files/BackupDevice.h"

#include <QCoreApplication>
#include <QHash>
#include <optional>

namespace opentop {

class Profile;

// What one drive of a unit must hold once it is set up: the recipe position's settings and this
// unit's per-unit values, encoded for the variant the drive turned out to be, as the
// BackupDevice the Restorer writes from (only what differs, in dependency order, read back).
class EolTarget
{
    Q_DECLARE_TR_FUNCTIONS(opentop::EolTarget)
public:
    // `unitValues`: this unit's values by parameter name, in engineering units. Nothing when a
    // value cannot be encoded or a per-unit value is missing; `error` says which, by label.
    static std::optional<BackupDevice> build(const Profile& profile, const RecipePosition& position,
                                             const QString& variant,
                                             const QHash<QString, double>& unitValues,
                                             QString* error);
};

} // namespace opentop
