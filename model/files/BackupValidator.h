#pragma once

#include "model/files/BackupDevice.h"
#include "model/profile/Profile.h"

#include <QCoreApplication>
#include <QStringList>

namespace opentop {

// Checks a drive's settings as a backup holds them against its profile, before they are
// trusted: by the file loader (is this a file we wrote?) and by a restore (may these values
// go to this drive?). Every problem names the parameter; value problems name the allowed values.
class BackupValidator
{
    Q_DECLARE_TR_FUNCTIONS(opentop::BackupValidator)
public:
    // What a value must suit when the variant is not known.
    enum class UnknownVariant
    {
        AnyMayFit, // a file from a drive that did not tell: the value suited the drive it came from
        AllMustFit, // a write to a drive that does not tell: the value must suit every variant
    };

    // Every parameter known, part of backups, present once, with the right number of registers.
    static QStringList checkStructure(const Profile& profile, const BackupDevice& device);
    // Every value allowed for `variant`, with the controlling values the device itself holds.
    static QStringList checkValues(const Profile& profile, const BackupDevice& device,
                                   const QString& variant, UnknownVariant unknown);
};

} // namespace opentop
