#pragma once

#include <QCoreApplication>
#include <QString>
#include <QVector>
#include <optional>

namespace opentop {

class Profile;

// How a family's speed loop is tuned, from its profile: the "tuning" section (the controller's
// PID period and output scale, its open-loop mode and closed-loop modes with their feedback)
// and the roles that name the gains, the speed mode, the communication-loss time and the load
// current. The controller's PID form is described in docs/tuning.md.
struct TuningSpec
{
    Q_DECLARE_TR_FUNCTIONS(opentop::TuningSpec)
public:
    struct ClosedLoopMode
    {
        int mode = 0;
        QString feedback; // the parameter the loop regulates, in the speed command's raw units
    };

    int periodMs = 1;              // the controller's PID period
    double outputFullScale = 1000; // PID output (raw open-loop command) at 100 % duty
    int openLoopMode = 0;          // the speed mode whose command is the duty itself
    QVector<ClosedLoopMode> closedLoopModes;
    QString gainP, gainI, gainD, dPeriod; // parameters
    QString store;                        // command that stores the gains
    qint64 storeValue = 1;
    QString speedMode, command, commLossTime, loadCurrent, output;
    QString currentLimit; // the drive's current limit (optional): the plant model's

    const ClosedLoopMode* closedLoop(int mode) const;
    QStringList gainParameters() const { return {gainP, gainI, gainD, dPeriod}; }

    // Nothing and *error (naming what is missing) when the profile cannot be tuned.
    static std::optional<TuningSpec> of(const Profile& profile, QString* error);
};

} // namespace opentop
