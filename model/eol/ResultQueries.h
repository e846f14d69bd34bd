#pragma once

#include "eol/UnitRecord.h"

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
    // Every record of a serial number, whole, oldest first (a certificate, a trace).
    std::optional<QVector<UnitRecord>> history(const QString& serial, QString* error) const;

    // (recipe name, serial) of the units `filter` finds that were already tested for that recipe
    // before filter.from: a report over a time range gives them to YieldReport so that a
    // retest is never taken for a first pass. Empty when the filter has no start.
    std::optional<QSet<QPair<QString, QString>>> testedBefore(const ResultFilter& filter,
                                                              QString* error) const;

private:
    static UnitDrive driveFrom(const QSqlQuery& q, int first);

    ResultDatabase& database_;
};

} // namespace opentop
