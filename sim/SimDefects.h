#pragma once

#include "sim/SimDefectSpec.h"

#include <QCoreApplication>
#include <QStringList>
#include <optional>

namespace opentop {

class Profile;

// A simulated drive's defects as its device applies them: SimDefectSpec checked against the
// drive's profile (alarm codes from its alarm table, parameter names and addresses resolved).
// What an end-of-line test must catch: another firmware, a motor that cannot reach its speed,
// a load too high, an alarm while running, a setting that does not stick.
struct SimDefects
{
    Q_DECLARE_TR_FUNCTIONS(opentop::SimDefects)
public:
    SimDefectSpec spec; // as written, for the console's list

    std::optional<quint16> firmware;
    std::optional<double> maxSpeed; // DBU r/min, DC commutations per second
    bool stall = false;
    double loadOffset = 0;
    double loadScale = 1;
    std::optional<int> alarmCode; // DBU: the alarm table's code; DC: 0, the stall stop
    qint64 alarmAfterMs = 0;
    QStringList noStick; // parameter names
    QStringList noStore;
    std::optional<double> turnaroundMs; // with wire timing: this drive's own answer delay

    bool any() const { return !spec.isEmpty(); }
    // The speed magnitude the motor reaches when `magnitude` is commanded.
    double reachable(double magnitude) const;
    // True when the defect holds the motor below `magnitude`.
    bool limits(double magnitude) const { return reachable(magnitude) < magnitude; }
    double load(double normal) const { return normal * loadScale + loadOffset; }

    // Checks `spec` against `profile`; on error returns nothing and sets *error to a message
    // naming what is allowed.
    static std::optional<SimDefects> resolve(const SimDefectSpec& spec, const Profile& profile,
                                             QString* error);
};

} // namespace opentop
