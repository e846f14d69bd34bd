#pragma once

#include <QCoreApplication>
#include <QString>
#include <QStringList>

namespace opentop {

class BusDrives;
class Profile;

// When the window must ask for a drive's variant, and what to tell the user it changes. A DBU
// reports only "DBU": whether it is a DBU200 or a DBU400 decides its allowed speeds (and says
// its voltage and power). Asked once per drive and connection, at the first moment it matters:
// before a write or an edit of a setting whose allowed values depend on it, a backup (the file
// records it), a start. The answer is kept by BusDrives (and for the bus by BusMemory); "not
// known" is kept too, and values are then checked against every variant.
class VariantNeed
{
    Q_DECLARE_TR_FUNCTIONS(opentop::VariantNeed)
public:
    enum class Purpose
    {
        Write,  // `parameters` are about to be edited or written
        Backup, // the file records the variant
        Start,  // the motor is about to run
    };

    // Whether to ask now: the drive is identified, of a family with variants, does not report
    // its own, nobody named it, it was not asked this connection, and — for a write — one of
    // `parameters` has allowed values that depend on the variant.
    static bool needed(const BusDrives& drives, int slave, Purpose purpose,
                       const QStringList& parameters = {});
    // The parameters of `profile` whose allowed values differ between its variants.
    static QStringList dependent(const Profile& profile);
    // What the choice changes: each variant's description and the allowed values that differ.
    static QString whatItChanges(const Profile& profile);
    // The question for `slave`: which variant, why now, what it changes, and the variant chosen
    // for this bus last time (`remembered`, may be empty).
    static QString question(const BusDrives& drives, int slave, Purpose purpose,
                            const QString& remembered = QString());
};

} // namespace opentop
