#pragma once

// The plain parts of an end-of-line recipe (docs/recipe-format.md). Values are in engineering
// units, parameters are named by their stable profile names; what a value may be is decided by
// RecipeChecker against the profiles, never here.

#include <QJsonValue>
#include <QString>
#include <QStringList>
#include <QVector>
#include <optional>

namespace opentop {

// One setting the run writes: "spno2.speed" = 1500 (r/min), "spno2.direction" = "CW".
struct RecipeSetting
{
    QString name;
    QJsonValue value; // a number in engineering units, or text (an enumeration label, a string)
    QString unit;     // optional; when given it must be the parameter's unit
};

// A setting whose value differs per unit (a speed trimmed per machine), within [min, max].
struct RecipeUnitValue
{
    enum class Source
    {
        Csv,     // a CSV file keyed by serial number (UnitValuesCsv)
        Operator // typed by the operator when the unit is tested
    };
    QString name;
    double min = 0;
    double max = 0;
    QString unit; // optional; when given it must be the parameter's unit
    Source source = Source::Operator;
};

// Lower and upper limits of one measured value. `statistic` says what is measured of the
// parameter: "min", "mean" or "max" over a hold step, "value" for a read step.
struct RecipeLimit
{
    QString parameter;
    QString statistic;
    std::optional<double> lower;
    std::optional<double> upper;
    QString unit; // the parameter's unit ("" for unitless values)
};

// One declarative test step. Which fields a step uses depends on its type.
struct RecipeStep
{
    enum class Type
    {
        Priority,  // take communication priority (the "motionPriority" role)
        Select,    // select running data SPno `spno` (the "select" role)
        Speed,     // set the speed command to `speed` (the "speedCommand" role); runs the motor
        Start,     // start in `direction` ("cw" or "ccw")
        WaitSpeed, // wait until the speed is within `tolerance` of `target` within `timeout`
        Hold,      // run for `duration` measuring `limits` (min/mean/max of live values)
        NoAlarm,   // no alarm or warning was raised since the run started
        Stop,      // stop; stopped within `deceleration` + `margin`
        Read       // read `limits[0].parameter` and compare it with its limits or `equals`
    };
    Type type = Type::Stop;
    int spno = 0;                       // Select: 1–8
    double speed = 0;                   // Speed: in the speed command's unit
    QString direction;                  // Start: "cw" or "ccw"
    std::optional<double> target;       // WaitSpeed: none = the drive's own target speed
    double tolerance = 0;               // WaitSpeed, in the speed's unit
    double timeout = 0;                 // WaitSpeed, s
    double duration = 0;                // Hold, s
    std::optional<double> deceleration; // Stop, s; none = the drive's setting
    double margin = 0;                  // Stop, s
    QString unit;                       // Speed, WaitSpeed: optional, must be the value's unit
    QString equals;                     // Read: the expected text (enumerations, strings)
    QVector<RecipeLimit> limits;        // Hold: measured statistics; Read: the read value
};

// One drive of the unit, at a fixed machine number of the fixture.
// What a station does with a serial tested before (docs/eol-results.md, "Retests").
struct RecipeRetest
{
    enum class Passed
    {
        Technician, // a serial that passed before is tested again only when a technician says so
        Refuse,     // never again under this station
        Allow       // like any other retest
    };
    int maxAttempts = 3; // verdicts a serial may get under this recipe version; 0: no limit
    Passed passed = Passed::Technician;
    bool operator==(const RecipeRetest& o) const
    {
        return maxAttempts == o.maxAttempts && passed == o.passed;
    }
    bool operator!=(const RecipeRetest& o) const { return !(*this == o); }
};

struct RecipePosition
{
    int machineNumber = 0;
    QString name;         // "left conveyor"; optional
    QString family;       // "dbu", "dcpid"
    QStringList variants; // allowed variants; empty: any variant of the family
    // When the drive does not report its variant and the profile's probe does not prove it:
    // "" (a single allowed variant is taken, recorded as assumed), "required" (the unit fails
    // as an identity error), "operator" (the operator running the unit confirms the single
    // allowed variant; the record keeps who). RecipeVariantCheck decides.
    QString variantProof;
    QStringList firmware; // allowed firmware versions ("1.5"); empty: any
    QVector<RecipeSetting> settings;
    QVector<RecipeUnitValue> unitValues;
    QVector<RecipeStep> steps;
};

} // namespace opentop
