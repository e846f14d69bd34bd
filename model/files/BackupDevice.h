#pragma once

#include "model/profile/ParamValue.h"
#include "model/profile/Profile.h"
#include "model/profile/ValueContext.h"

#include <QString>
#include <QVector>

namespace opentop {

// One setting as a backup holds it. The registers are what counts; value, text and unit are
// derived from them for people reading the file.
struct BackupParameter
{
    QString name;
    QVector<quint16> registers;
};

// The settings of one drive: read from it, loaded from a file, or the profile's factory state.
class BackupDevice
{
public:
    int slave = 0;
    QString family;
    QString variant; // empty when the drive does not tell and nobody named it
    QString model;
    QString firmware;
    QString name;        // the device name register ("DBU")
    QString machineName; // the user's name for the machine ("Infeed conveyor 3"), empty: none
    QVector<BackupParameter> parameters; // profile order

    const BackupParameter* parameter(const QString& parameterName) const;
    QStringList parameterNames() const;
    // The variant and this device's own values, which decide what other values mean (the
    // input function codes depend on the control mode held in the same set).
    ValueContext context(const Profile& profile) const;
    ParamValue value(const Profile& profile, const QString& parameterName) const;
    // "2.5 s", "CW/STOP"; empty when the device does not hold the parameter.
    QString text(const Profile& profile, const QString& parameterName) const;
    QString unit(const Profile& profile, const QString& parameterName) const;
    // "drive 1 (DBU200-D)", "drive 1 (Infeed conveyor 3, DBU200-D)" (DriveName::withModel).
    QString title() const;
};

} // namespace opentop
