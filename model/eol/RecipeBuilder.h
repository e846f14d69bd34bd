#pragma once

#include "model/eol/Recipe.h"

#include <QCoreApplication>
#include <optional>

namespace opentop {

class BackupDevice;
class BackupFile;
class Profile;
class ProfileRegistry;

// Creates a recipe from a golden unit: from a backup file, or from a drive's settings as
// BackupReader reads them off the bus (the same BackupDevice). Every setting a backup holds
// becomes a recipe setting in engineering units (enumerations by their label), except the
// communication settings; the drive's variant and firmware become the allowed ones; and each
// position gets the family's default test steps, which RecipeChecker accepts as they are.
class RecipeBuilder
{
    Q_DECLARE_TR_FUNCTIONS(opentop::RecipeBuilder)
public:
    explicit RecipeBuilder(const ProfileRegistry& registry);

    std::optional<Recipe> fromBackup(const BackupFile& file, const QString& product,
                                     const QString& revision, QString* error) const;
    std::optional<Recipe> fromDevices(const QVector<BackupDevice>& devices, const QString& product,
                                      const QString& revision, QString* error) const;
    std::optional<RecipePosition> positionFrom(const BackupDevice& device, QString* error) const;

    // DBU: priority, select the first running data with a speed, start in its direction, wait
    // for its speed (±5 %, its acceleration time + 5 s), hold 5 s measuring speed and load, stop,
    // no alarm. DC controller: set the speed command to 30 % of its range, wait for it (speed
    // loop mode) or hold measuring that the motor turns, its current and PWM, stop.
    static QVector<RecipeStep> defaultSteps(const Profile& profile, const RecipePosition& position);

private:
    const ProfileRegistry& m_registry;
};

} // namespace opentop
