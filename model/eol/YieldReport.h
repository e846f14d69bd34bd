#pragma once

#include "model/eol/ShiftPlan.h"
#include "model/eol/UnitRecord.h"

#include <QCoreApplication>
#include <QHash>
#include <QMap>
#include <QPair>
#include <optional>

namespace opentop {

class ResultDatabase;
struct ResultFilter;

// Yield as docs/eol-results.md defines it, computed in one place for the station's screen, the
// results browser and `eol results --yield`. Only verdicts count (pass, fail): a station error,
// an abort, a unit still running or interrupted is no test of the unit and stays out of every
// yield. A recipe is its checksum: two files with one name and revision are two rows.
//
// A serial counts once, in the row (and shift) of its first verdict under that recipe:
// first-pass yield = passed at its first verdict, second-pass yield = passed by its second,
// last-pass yield = its latest verdict is a pass. A serial whose first verdict came before the
// period looked at is a retest here, not a first test.
struct YieldRow
{
    QString checksum;
    QString recipe; // its name and revision, as the records give them
    QString revision;
    QString shift;                     // empty in a per-recipe row
    int serials = 0;                   // distinct serials whose first verdict is here
    int firstPass = 0;                 // of those, passed at the first verdict
    int secondPass = 0;                // ... passed by the second
    int lastPass = 0;                  // ... whose latest verdict is a pass
    int records = 0;                   // every record here, retests and station errors included
    int verdicts = 0;                  // pass and fail records
    int passed = 0;                    // pass records
    int failed = 0;                    // fail records
    int stationErrors = 0;             // error and aborted records: no verdict on the unit
    int running = 0;                   // still running or interrupted (never a pass)
    QMap<QString, int> failureReasons; // fail records, by their reason
    QMap<QString, int> stationReasons; // records without a verdict, by their reason
    double firstPassYield() const { return serials ? double(firstPass) / serials : 0.0; }
    double secondPassYield() const { return serials ? double(secondPass) / serials : 0.0; }
    double lastPassYield() const { return serials ? double(lastPass) / serials : 0.0; }
    QString title() const; // "Conveyor C-200 rev. A"
};

class YieldReport
{
    Q_DECLARE_TR_FUNCTIONS(opentop::YieldReport)
public:
    // What came before a period, per (recipe checksum, serial): its verdicts then.
    struct Before
    {
        int verdicts = 0;
        bool passed = false;
    };
    using Earlier = QHash<QPair<QString, QString>, Before>;

    struct Tables
    {
        QVector<YieldRow> perRecipe;
        QVector<YieldRow> perShift;
        QVector<UnitRecord> units; // the units found, oldest first
    };
    // The units `filter` finds and their yield (the one computation every reader uses).
    static std::optional<Tables> query(ResultDatabase& db, const ResultFilter& filter,
                                       const ShiftPlan& plan, QString* error);

    // Rows per recipe, in name, revision and checksum order.
    static QVector<YieldRow> perRecipe(const QVector<UnitRecord>& units,
                                       const Earlier& earlier = {});
    // Rows per recipe and shift; a serial's first verdict counts in the shift it was given in.
    static QVector<YieldRow> perShift(const QVector<UnitRecord>& units, const ShiftPlan& plan,
                                      const Earlier& earlier = {});
    // The sum of rows (a station's screen: one recipe, one station, this shift).
    static YieldRow total(const QVector<YieldRow>& rows);
    // "first-pass yield 42.9 % (3 of 7 serials) · second-pass 57.1 % · last-pass 71.4 %": how
    // every screen says it.
    static QString yieldText(const YieldRow& row);
    static QString percentText(double share); // "42.9 %", "–" for no serial
    // The reason a report shows for a record that did not pass.
    static QString reasonOf(const UnitRecord& unit);
};

} // namespace opentop
