#pragma once

#include "model/eol/ResultSpool.h"
#include "model/eol/StationLease.h"
#include "model/eol/UnitRecord.h"

#include <QCoreApplication>
#include <memory>
#include <optional>

namespace opentop {

class ResultDatabase;
class ResultStore;

// Where a station's unit records go, on the results thread (ResultWriter): the results database
// when it answers, else the station's spool (ResultSpool), from which they are sent in order
// once it answers again. Older spooled entries always go first, so records reach the database
// in the order the station made them. Also holds the station's lease (StationLease): renewed and
// swept by heartbeat().
class ResultSink
{
    Q_DECLARE_TR_FUNCTIONS(opentop::ResultSink)
public:
    struct Saved
    {
        QString error;        // empty: the record is safe (in the database or the spool)
        bool spooled = false; // kept on the station's disk, not yet in the database
        QString why;          // spooled: why the database did not take it
    };
    struct Flushed
    {
        int waiting = 0; // entries still in the spool (-1: the spool cannot be read)
        int sent = 0;
        QString error; // why the oldest is still waiting
    };

    ResultSink();
    ~ResultSink();

    // Opens the database; for a station (non-empty `station`) also takes a lease, opens the
    // spool in `spoolFolder`, sends what it holds and marks leftovers interrupted.
    bool open(const QString& url, const QString& station, const QString& spoolFolder,
              QString* error);
    void close(); // ends the lease when the database still answers
    bool isOpen() const { return bool(m_db); }
    ResultDatabase* database() const { return m_db.get(); }
    QString displayText() const;
    QString spoolPath() const { return m_spool ? m_spool->path() : QString(); }
    QString spoolError() const { return m_spoolError; }
    // Leftovers the last open() or heartbeat() marked interrupted.
    QVector<StationLease::Leftover> takeLeftovers();

    // The unit's 'running' row (an id and start time are given when it has none).
    Saved begin(UnitRecord& record);
    Saved finish(const UnitRecord& record);
    // Sends the spool's entries, oldest first, until it is empty or the database fails.
    Flushed flush();
    int waiting();
    // Renews the lease and marks other processes' leftovers interrupted.
    void heartbeat();

private:
    enum class Outcome
    {
        Done,
        Unreachable, // no connection could be made: the spool keeps it
        Refused      // the database answered and said no: an error, never spooled
    };
    template <typename Write> Outcome write(Write write, QString* error);
    bool reconnect(QString* error);
    Saved save(ResultSpool::Kind kind, UnitRecord& record);
    Outcome deliver(const ResultSpool::Entry& entry, QString* error);

    QString m_url;
    std::unique_ptr<ResultDatabase> m_db;
    std::unique_ptr<ResultStore> m_store;
    std::unique_ptr<ResultSpool> m_spool;
    std::optional<StationLease> m_lease;
    QString m_spoolError;
    QVector<StationLease::Leftover> m_leftovers;
};

} // namespace opentop
