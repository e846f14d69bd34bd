#pragma once

#include "model/profile/ValueContext.h"

#include <QCoreApplication>
#include <QString>
#include <functional>
#include <optional>

namespace opentop {

class Profile;

// The running data SPno1–SPnoN of a drive family (profile parameters "spnoN.speed",
// "spnoN.direction", "spnoN.accel", "spnoN.decel") and the advice that goes with them.
//
// Deceleration at high speed (DBU manual 4-1 remark, 9 and 12-2 remark 2): "When reducing at
// high speed, please set the speed decreasing time to more than 2 seconds." The manual does not
// say what high speed is; OpenTOP takes it as 1500 r/min and above, half the rated speed
// (docs/errata.md). The rule lives here so that every page, the multi-drive dialog and the
// command line give the same warning; it is advice, never a refusal (0.5 s is a valid setting).
class RunningData
{
    Q_DECLARE_TR_FUNCTIONS(opentop::RunningData)
public:
    static constexpr double kMinDecelerationS = 2.0;
    static constexpr double kHighSpeedRpm = 1500.0;

    // "spno3.speed"; empty when the profile has no such parameter.
    static QString parameter(const Profile& profile, int spno, const QString& field);
    // The number of SPnos with a speed (8 for a DBU, 0 without running data).
    static int count(const Profile& profile);
    // The SPno a parameter belongs to (3 for "spno3.decel"), 0 for none; `field`: "decel".
    static int spnoOf(const QString& name, QString* field = nullptr);
    // The running data the drive runs (or runs when started), 1-based, from the raw value of
    // its "selected" role's parameter (a status field on a DBU, which follows the inputs M0–M2
    // in I/O priority as well as the selection command); nothing when not read or not known.
    static std::optional<int>
    selected(const Profile& profile,
             const std::function<std::optional<double>(const QString&)>& raw);

    // The warning for SPno `spno` with this speed (r/min) and deceleration (s); empty when
    // there is none or a value is unknown.
    static QString decelerationWarning(int spno, std::optional<double> speedRpm,
                                       std::optional<double> decelerationS);
    // The same for a parameter about to hold `raw` (a speed or deceleration of an SPno), the
    // other values taken from `values` (the drive's, or as they will be written).
    static QString warningFor(const Profile& profile, const QString& name, qint64 raw,
                              const ValueContext& values);
    // Every SPno's warning for the values in `values`, one line each.
    static QStringList warnings(const Profile& profile, const ValueContext& values);
    // The same in one sentence for a page: the factory defaults already give five SPnos a 0.5 s
    // deceleration from 1700 r/min and more, and five paragraphs would be read by nobody.
    static QString summary(const Profile& profile, const ValueContext& values);
};

} // namespace opentop
