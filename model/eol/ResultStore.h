#pragma once

#include "eol/UnitRecord.h"

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
    // The record's final status (not running) with all it holds, in one transaction; the unit
    // must have been begun and still be running. Sets an ended time (now) when it has none.
    bool finishUnit(UnitRecord& record, QString* error);
    // Rows of `station` still 'running' that started before `before` (this station's own start)
    // become 'interrupted' with a reason in words. Returns how many, -1 on an error.
    int markInterrupted(const QString& station, const QDateTime& before, QString* error);

    // Called inside finishUnit's transaction once every child row is written, before the status
    // changes and the commit (tests kill the process here); empty by default.
    void setInTransactionHook(std::function<void()> hook) { hook_ = std::move(hook); }

    static QString interruptedReason();

private:
    bool writeChildren(const UnitRecord& record, QString* error);

    ResultDatabase& database_;
    std::function<void()> hook_;
};

} // namespace opentop
