#pragma once

#include "eol/UnitRecord.h"

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
// Jobs run in the order they are given, with a ResultDatabase and ResultStore that live on the
// writer's thread (a QSqlDatabase connection belongs to its thread). Each answer comes back on
// the thread of the `context` object given with the job, later, never inside the call; none
// comes when the context is gone by then. Destroying the writer finishes every job already
// given (a unit's record is never dropped half-way) and then closes the database.
class ResultWriter : public QObject
{
    Q_OBJECT
public:
    struct Opened
    {
        bool ok = false;
        QString error;       // why not, naming the database (never its password)
        QString displayText; // the database as a user may read it
        int interrupted = 0; // the station's leftovers now recorded as interrupted
    };
    using OpenDone = std::function<void(const Opened&)>;
    using BeginDone = std::function<void(const UnitRecord& begun, const QString& error)>;
    using FinishDone = std::function<void(const QString& error)>;

    explicit ResultWriter(QObject* parent = nullptr);
    ~ResultWriter() override;

    // Opens `url` (made when a missing SQLite file) and turns the rows `station` left running
    // into interrupted ones (ResultStore::markInterrupted; none when `station` is empty). A
    // database already open is closed once the new one is.
    void open(const QString& url, const QString& station, QObject* context, OpenDone done);
    // The same, waiting for the answer in a local event loop (the command line, start-up).
    Opened openAndWait(const QString& url, const QString& station);
    bool isOpen() const { return m_open; }
    bool isOpening() const { return m_opening > 0; }
    QString displayText() const { return m_displayText; }

    // ResultStore::beginUnit: `begun` is the record with its id and start time.
    void beginUnit(const UnitRecord& record, QObject* context, BeginDone done);
    // ResultStore::finishUnit: the whole record in one transaction.
    void finishUnit(const UnitRecord& record, QObject* context, FinishDone done);

    // Runs `job` on the writer's thread with the open database (null when none), then `done` on
    // `context`'s thread: a query (what it finds travels in what both capture).
    void run(QObject* context, std::function<void(ResultDatabase* db)> job,
             std::function<void()> done);

    // Jobs given and not yet answered (tests, and the screen's "recording" state).
    int pending() const { return m_pending; }

private:
    struct State;
    // Runs `job` on the writer's thread, then `here` with its result on this object's thread
    // and `answer` on `context`'s.
    template <typename Result>
    void post(QObject* context, std::function<Result(State&)> job,
              std::function<void(const Result&)> answer,
              std::function<void(const Result&)> here = {});

    QThread m_thread;
    QObject* m_worker; // lives on m_thread: jobs are queued to it
    std::shared_ptr<State> m_state;
    bool m_open = false;
    int m_opening = 0;
    int m_pending = 0;
    QString m_displayText;
};

} // namespace opentop
