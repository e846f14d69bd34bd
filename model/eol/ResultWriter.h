#pragma once

#include "model/eol/ResultSink.h"
#include "model/eol/UnitRecord.h"

#include <QCoreApplication>
#include <QObject>
#include <QThread>
#include <functional>
#include <memory>

namespace opentop {

class ResultDatabase;

// The results database on a thread of its own, for a station and the results browser: opening
// it, beginning and finishing unit records, queries never make the caller's thread wait. A
// PostgreSQL server across the factory, or a SQLite file another station is writing, can take
// seconds (SQLite's busy timeout is 10 s); the operator screen and its STOP keys must not freeze
// meanwhile.
//
// Jobs run in the order they are given, with a ResultSink that lives on the writer's thread (a
// QSqlDatabase connection belongs to its thread). Each answer comes back on the thread of the
// `context` object given with the job, later, never inside the call; none comes when the context
// is gone by then. Destroying the writer finishes every job already given (a unit's record is
// never dropped half-way) and then closes the database.
//
// A station's writer (open() with a station name) keeps records the database cannot take in the
// station's spool and sends them by itself once it answers again (2, 4 … 30 s apart), and renews
// the station's lease every StationLease::kRenewS seconds.
class ResultWriter : public QObject
{
    Q_OBJECT
public:
    struct Opened
    {
        bool ok = false;
        QString error;       // why not, naming the database (never its password)
        QString displayText; // the database as a user may read it
        // Units of this station left running by a process that is gone, now interrupted.
        QVector<StationLease::Leftover> interrupted;
        int waiting = 0;    // spooled records not yet sent
        QString spoolError; // the spool cannot be used (records then need the database)
        QString spoolPath;
    };
    using Saved = ResultSink::Saved;
    using OpenDone = std::function<void(const Opened&)>;
    using BeginDone = std::function<void(const UnitRecord& begun, const Saved& saved)>;
    using FinishDone = std::function<void(const Saved& saved)>;

    explicit ResultWriter(QObject* parent = nullptr);
    ~ResultWriter() override;

    // Where a station's spool files are (default ResultSpool::defaultFolder()); before open().
    void setSpoolFolder(const QString& folder) { m_spoolFolder = folder; }

    // Opens `url` (made when a missing SQLite file). With a `station` name: takes a lease, sends
    // what the spool holds, and marks units left running by gone processes interrupted. A
    // database already open is closed once the new one is.
    void open(const QString& url, const QString& station, QObject* context, OpenDone done);
    // The same, waiting for the answer in a local event loop (the command line, start-up).
    Opened openAndWait(const QString& url, const QString& station);
    bool isOpen() const { return m_open; }
    bool isOpening() const { return m_opening > 0; }
    QString displayText() const { return m_displayText; }
    QString spoolPath() const { return m_spoolPath; }

    // The unit's 'running' row: `begun` is the record with its id and start time.
    void beginUnit(const UnitRecord& record, QObject* context, BeginDone done);
    // The whole record in one transaction.
    void finishUnit(const UnitRecord& record, QObject* context, FinishDone done);
    // Sends the spool now instead of at the next try.
    void flushNow();

    // Runs `job` on the writer's thread with the open database (null when none), then `done` on
    // `context`'s thread: a query (what it finds travels in what both capture).
    void run(QObject* context, std::function<void(ResultDatabase* db)> job,
             std::function<void()> done);

    // Jobs given and not yet answered (tests, and the screen's "recording" state).
    int pending() const { return m_pending; }
    // Records in the spool as last counted, and why the oldest is still there.
    int waiting() const { return m_waiting; }
    QString waitingError() const { return m_waitingError; }

signals:
    void waitingChanged(int waiting, const QString& error);

private:
    struct State;
    // Runs `job` on the writer's thread, then `here` with its result on this object's thread
    // and `answer` on `context`'s.
    template <typename Result>
    void post(QObject* context, std::function<Result(State&)> job,
              std::function<void(const Result&)> answer,
              std::function<void(const Result&)> here = {});
    void reportWaiting(int waiting, const QString& error); // on this object's thread

    QThread m_thread;
    QObject* m_worker; // lives on m_thread: jobs are queued to it
    std::shared_ptr<State> m_state;
    QString m_spoolFolder;
    bool m_open = false;
    int m_opening = 0;
    int m_pending = 0;
    int m_waiting = 0;
    QString m_waitingError;
    QString m_displayText;
    QString m_spoolPath;
};

} // namespace opentop
