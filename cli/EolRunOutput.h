#pragma once

#include <QString>

namespace opentop {

class CliContext;
class EolRun;
class ModbusClient;
class Recipe;
struct UnitRecord;

// What `eol run` shows of a unit while it runs and when it ends: progress lines for people on
// standard error, the measurements and the verdict on standard output for scripts, or one JSON
// object per line (--json) for a PLC or MES; then what became of the record and the motors.
class EolRunOutput
{
public:
    // Shows the run's progress and measurements from now on; a port that vanishes ends the
    // unit at once and sets *lost.
    static void follow(CliContext& context, EolRun* run, ModbusClient* client, bool* lost);
    // The unit's verdict (its record as the run ended it), whether it was recorded or kept in
    // the station's spool at `spoolPath`, and every motor not confirmed stopped.
    static void verdict(CliContext& context, const EolRun& run, const UnitRecord& record,
                        const Recipe& recipe, const QString& spoolPath);
    static QString seconds(const EolRun& run); // since the unit began, "12.3"
};

} // namespace opentop
