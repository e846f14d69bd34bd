#pragma once

#include <QDateTime>
#include <QString>
#include <QStringList>
#include <QVector>
#include <optional>

namespace opentop {

// One unit's end-of-line record as the results database keeps it (docs/eol-results.md): who,
// where, when, with which recipe, what each drive was, every value written and its proof, every
// measured value with its limits, and the verdict. The recipe is named by its name, revision and
// checksum only, so that a record stays readable when the recipe file is long gone.
enum class UnitStatus
{
    Running,     // begun, not finished: the station is testing it, or was killed while it did
    Interrupted, // found still running after its station restarted: never a pass
    Pass,
    Fail,
    Aborted, // the operator cancelled the run before a verdict
    // The station could not test the unit (no drive answers, a motor already turning, an alarm
    // latched before the test): no verdict on the unit, kept out of yield and retest counts.
    Error
};

QString unitStatusName(UnitStatus status); // "running", "interrupted", "pass", "fail", "aborted",
                                           // "error"
std::optional<UnitStatus> unitStatusFromName(const QString& name);

// How a drive's variant was known. Only `read` and `probed` are proof on the bus; `assumed` is
// never shown as known (the certificate says "assumed").
enum class VariantSource
{
    None,      // no variant: the family has none, or the recipe allows any and none was found
    Read,      // the drive reports it (its identification)
    Probed,    // the profile's variant probe proved it (UnitDrive::variantProof says how)
    Confirmed, // a person stated it (the record says who): eol run --variant, a recipe option
    Assumed    // the recipe's only variant, taken without proof
};

QString variantSourceName(VariantSource source); // "", "read", "probed", "confirmed", "assumed"
std::optional<VariantSource> variantSourceFromName(const QString& name);

// A drive of the unit, at its fixture position (the machine number set on its switches).
struct UnitDrive
{
    int machineNumber = 0;
    QString model;   // family/model, e.g. "DBU"
    QString variant; // e.g. "dbu200"
    QString firmware;
    VariantSource variantSource = VariantSource::None;
    QString variantProof; // the probe and its answer, or who confirmed it
    bool operator==(const UnitDrive& o) const;
};

// A setting the recipe gives: what was written, and whether reading it back proved it.
struct WrittenValue
{
    int machineNumber = 0;
    QString parameter; // internal name, for tracing; user text shows the label
    QString label;
    QString value;        // engineering value as text, with its unit: "1500 r/min"
    bool written = false; // false: the drive already held it, nothing was sent
    bool verified = false;
    QString readBack; // what the drive answered, with its unit
    bool operator==(const WrittenValue& o) const;
};

struct Measurement
{
    int machineNumber = 0;
    QString step;     // the recipe step that measured it, in words
    QString quantity; // "speed mean", "load max"
    double value = 0;
    QString unit;
    std::optional<double> lower; // no limit when empty
    std::optional<double> upper;
    bool pass = false;
    bool operator==(const Measurement& o) const;
};

struct UnitRecord
{
    QString id; // unique over all stations (a UUID), given by beginUnit() when empty
    QString serial;
    QString station;
    QString operatorName;
    QDateTime started; // UTC, milliseconds
    QDateTime ended;   // UTC; invalid while running
    QString recipeName;
    QString recipeRevision;
    QString recipeChecksum;
    // The recipe approval the unit ran under (access/RecipeApprovals) and its approver; empty
    // on a station without users (unmanaged) and on records from before approvals.
    QString approvalId;
    QString approver;
    UnitStatus status = UnitStatus::Running;
    // Which verdict of this serial under this recipe (checksum) this is: 1 for the first test,
    // 2 for the first retest… A record without a verdict (error, aborted) has the number its
    // verdict would have had. 0: recorded before attempts were counted.
    int attempt = 0;
    QString failureReason; // the first failure, in words; empty for a pass
    QVector<UnitDrive> drives;
    QVector<WrittenValue> writtenValues;
    QVector<Measurement> measurements;
    QStringList traffic; // decoded bus traffic around the failure, one line each

    bool isPass() const { return status == UnitStatus::Pass; }
    // A pass or a fail: a verdict on the unit, as yield and retest limits count them.
    bool hasVerdict() const { return status == UnitStatus::Pass || status == UnitStatus::Fail; }
    bool operator==(const UnitRecord& o) const;
    bool operator!=(const UnitRecord& o) const { return !(*this == o); }
};

} // namespace opentop
