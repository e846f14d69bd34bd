#pragma once

#include "model/eol/UnitRecord.h"
#include "model/eol/YieldReport.h"

#include <QCoreApplication>
#include <QPair>
#include <QSet>
#include <optional>

class QSqlQuery;

namespace opentop {

class ResultDatabase;

// What to look for in the results database; empty parts match everything.
struct ResultFilter
{
    // A serial number; with a * (any characters) or ? (one character) in it, a pattern that
    // ignores case ("sn-10*"): what an operator types into a search field (serialsLike()).
    QString serial;
    QDateTime from;                   // started at or after (UTC)
    QDateTime to;                     // started before
    QString recipe;                   // recipe name
    QString checksum;                 // recipe checksum (one version of a recipe)
    std::optional<UnitStatus> status; // Pass matches 'pass' only: running/interrupted never do
    QString station;
    int limit = 0; // the newest `limit` units; 0: all

    bool serialIsPattern() const;
    // The SQL LIKE form of the pattern, in lower case, with \ as its escape character.
    QString serialLike() const;
};

// Reads unit records back (docs/eol-results.md).
class ResultQueries
{
    Q_DECLARE_TR_FUNCTIONS(opentop::ResultQueries)
public:
    explicit ResultQueries(ResultDatabase& database);

    // The units' own rows (no drives, values or traffic), oldest first. nullopt on an error.
    std::optional<QVector<UnitRecord>> find(const ResultFilter& filter, QString* error) const;
    // Adds each unit's drives (model, variant and how it was known) to units `find` gave.
    bool addDrives(QVector<UnitRecord>* units, QString* error) const;
    // One whole record; nullopt with *error when there is none or on an error.
    std::optional<UnitRecord> load(const QString& unitId, QString* error) const;
    // The serial's records begun before `record` (own rows), oldest first: what its
    // certificate lists as earlier tests.
    std::optional<QVector<UnitRecord>> earlierOf(const UnitRecord& record, QString* error) const;
    // Every record of a serial number, whole, oldest first (a certificate, a trace).
    std::optional<QVector<UnitRecord>> history(const QString& serial, QString* error) const;

    // The verdicts before filter.from of each (recipe checksum, serial) that `filter` finds
    // units of: a report over a time range gives them to YieldReport so that a retest is never
    // taken for a first pass. Empty when the filter has no start.
    std::optional<YieldReport::Earlier> testedBefore(const ResultFilter& filter,
                                                     QString* error) const;
    // The verdicts a serial has under a recipe (checksum), oldest first, and whether it passed
    // under any recipe: what a retest limit is decided on (RetestPolicy).
    struct SerialHistory
    {
        int verdicts = 0;        // pass and fail records under this checksum
        int failures = 0;        // of which fails
        bool passedAny = false;  // a pass under any recipe
        QStringList passedUnits; // unit ids of those passes, newest last
    };
    std::optional<SerialHistory> serialHistory(const QString& serial, const QString& checksum,
                                               QString* error) const;

private:
    QString unitColumns() const;   // the units' columns unitFrom() reads
    QString sourceColumns() const; // a drive's variant source and proof, or NULLs
    static UnitDrive driveFrom(const QSqlQuery& q, int first);

    ResultDatabase& database_;
};

} // namespace opentop
