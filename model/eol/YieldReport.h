#pragma once

#include "eol/ShiftPlan.h"
#include "eol/UnitRecord.h"

#include <QCoreApplication>
#include <QMap>
#include <QPair>
#include <QSet>

namespace opentop {

// First-pass yield and failure reasons (docs/eol-results.md), computed from the units' own rows
// (ResultQueries::find). A serial's first record for a recipe decides its first pass: only a
// 'pass' is one; a first record that is running, interrupted, failed or aborted is not.
struct YieldRow
{
    QString recipe;
    QString shift;                     // empty in a per-recipe row
    int serials = 0;                   // distinct serials whose first record for the recipe is here
    int firstPass = 0;                 // of those, passed the first time
    int records = 0;                   // every record here, retests included
    int running = 0;                   // still running or interrupted (counted, never as a pass)
    QMap<QString, int> failureReasons; // every record that is not a pass, by its reason
    double firstPassYield() const { return serials ? double(firstPass) / serials : 0.0; }
};

class YieldReport
{
    Q_DECLARE_TR_FUNCTIONS(opentop::YieldReport)
public:
    // (recipe name, serial) tested before the units given (ResultQueries::testedBefore): their
    // records here are retests, none of them a first record.
    using Earlier = QSet<QPair<QString, QString>>;

    // Rows per recipe (by name), in name order.
    static QVector<YieldRow> perRecipe(const QVector<UnitRecord>& units,
                                       const Earlier& earlier = {});
    // Rows per recipe and shift, in recipe then shift order; a serial's first record counts in
    // the shift it was tested in.
    static QVector<YieldRow> perShift(const QVector<UnitRecord>& units, const ShiftPlan& plan,
                                      const Earlier& earlier = {});
    // The reason a report shows for a record that did not pass.
    static QString reasonOf(const UnitRecord& unit);
};

} // namespace opentop
