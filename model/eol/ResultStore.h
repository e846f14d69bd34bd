#pragma once

#include "model/eol/UnitRecord.h"

#include <QCoreApplication>
#include <functional>

namespace opentop {

class ResultDatabase;

// Writes unit records so that none is ever lost or half-written (docs/eol-results.md):
// beginUnit() commits the unit's row as 'running' before anything is done to the drives, so a
// station killed mid-unit leaves a row that is visibly not a pass; finishUnit() writes every
// child row and the final status in one transaction, so the record is either complete or still
// 'running'; markInterrupted() turns a station's leftovers into 'interrupted' when it starts.
class ResultStore
{
    Q_DECLARE_TR_FUNCTIONS(opentop::ResultStore)
public:
    explicit ResultStore(ResultDatabase& database);

    // Gives the record an id (a UUID) and a start time (now, UTC) when it has none, and commits
    // its row with status 'running' and no children. The record's own status is left as it is:
    // it is what finishUnit() will record.
    bool beginUnit(UnitRecord& record, QString* error);
    // Gives a record without them its id and start time, as beginUnit() does (the spool keeps
    // them before the database sees the unit).
    static void identify(UnitRecord& record);
    // The record's final status (not running) with all it holds, in one transaction; the unit
    // must have been begun and still be running. Sets an ended time (now) when it has none.
    // A unit of this store's lease that another process marked interrupted meanwhile (its lease
    // looked dead while the database was out of reach) is finished too: it was not.
    bool finishUnit(UnitRecord& record, QString* error);
    // The lease (StationLease) that units begun from now on belong to; empty: none.
    void setLease(const QString& lease) { lease_ = lease; }
    QString lease() const { return lease_; }
    // A unit's status in the database ("running", "pass" …); empty when there is no such unit
    // or on an error (*error set).
    QString statusOf(const QString& unitId, QString* error);
    // Rows of `station` from before leases (no lease) still 'running' that started before
    // `before` become 'interrupted' with a reason in words. Returns how many, -1 on an error.
    // Rows with a lease are StationLease::sweep()'s.
    int markInterrupted(const QString& station, const QDateTime& before, QString* error);

    // Called inside finishUnit's transaction once every child row is written, before the status
    // changes and the commit (tests kill the process here); empty by default.
    void setInTransactionHook(std::function<void()> hook) { hook_ = std::move(hook); }

    static QString interruptedReason();

private:
    bool writeChildren(const UnitRecord& record, QString* error);

    bool hasLeases() const;
    bool hasAttempts() const; // schema 5: attempt numbers and the 'error' status

    ResultDatabase& database_;
    std::function<void()> hook_;
    QString lease_;
};

} // namespace opentop
