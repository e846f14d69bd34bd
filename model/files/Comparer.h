#pragma once

#include "model/files/BackupDevice.h"

#include <QCoreApplication>
#include <QStringList>
#include <QVector>

namespace opentop {

// Differences between two sets of settings of one family, by parameter name, each value shown
// with its unit as its own side means it: file against drive, drive against drive, file
// against file, or a drive or file against the profile's factory defaults.
class Comparer
{
    Q_DECLARE_TR_FUNCTIONS(opentop::Comparer)
public:
    struct Difference
    {
        QString parameter;
        QString label;
        QString a; // "2.5 s"; empty when side A does not hold the parameter
        QString b;
        QVector<quint16> aRegisters;
        QVector<quint16> bRegisters;
    };

    struct Result
    {
        QString refusal;                 // why nothing could be compared (different families)
        QVector<Difference> differences; // profile order
        // Against factory defaults: parameters the manual gives no default for. Never a
        // difference: nobody can say what the factory value is.
        QStringList noDefault;
        QStringList notes; // e.g. "the variants differ: dbu200 and dbu400"
        int compared = 0;  // parameters both sides hold
    };

    static Result compare(const Profile& profile, const BackupDevice& a, const BackupDevice& b);
    static Result compareWithDefaults(const Profile& profile, const BackupDevice& a);
    // The factory state of `variant`: every backup setting with a documented default, each in
    // the context of the other defaults (the input defaults follow the default control mode).
    static BackupDevice factoryDefaults(const Profile& profile, const QString& variant,
                                        QStringList* undocumented = nullptr);
};

} // namespace opentop
