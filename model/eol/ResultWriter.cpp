#include "model/eol/ResultWriter.h"

#include "model/ModelLog.h"
#include "model/eol/ResultDatabase.h"

#include <QEventLoop>
#include <QPointer>
#include <QTimer>

namespace opentop {

// Touched only on the writer's thread.
struct ResultWriter::State
{
    ResultSink sink;
    QTimer* heartbeat = nullptr;
    QTimer* retry = nullptr;
    int retryS = 2;
    std::function<void(int, const QString&)> report; // to the writer's own thread

    // After anything that may change the spool: its count goes to the screen, and a spool that
    // holds records is tried again later, 2, 4 … 30 s apart.
    void spoolChanged(int waiting, const QString& error)
    {
        report(waiting, error);
        if (!retry)
            return;
        if (waiting == 0) {
            retry->stop();
            retryS = 2;
        } else if (!retry->isActive()) {
            retry->start(retryS * 1000);
            retryS = std::min(30, retryS * 2);
        }
    }
    void startTimers(QObject* owner)
    {
        if (heartbeat)
            return;
        heartbeat = new QTimer(owner);
        heartbeat->setInterval(StationLease::kRenewS * 1000);
        QObject::connect(heartbeat, &QTimer::timeout, owner, [this] { sink.heartbeat(); });
        heartbeat->start();
        retry = new QTimer(owner);
        retry->setSingleShot(true);
        QObject::connect(retry, &QTimer::timeout, owner, [this] { flush(); });
    }
    void flush()
    {
        const ResultSink::Flushed f = sink.flush();
        if (f.sent && retry)
            retryS = 2;
        spoolChanged(f.waiting, f.error);
    }
    void stopTimers()
    {
        delete heartbeat;
        delete retry;
        heartbeat = retry = nullptr;
    }
};

ResultWriter::ResultWriter(QObject* parent)
    : QObject(parent)
    , m_worker(new QObject)
    , m_state(std::make_shared<State>())
    , m_spoolFolder(ResultSpool::defaultFolder())
{
    m_state->report = [this](int waiting, const QString& error) {
        QMetaObject::invokeMethod(
            this, [this, waiting, error] { reportWaiting(waiting, error); }, Qt::QueuedConnection);
    };
    m_thread.setObjectName(QStringLiteral("results"));
    m_worker->moveToThread(&m_thread);
    m_thread.start();
}

ResultWriter::~ResultWriter()
{
    // Queued after every job already given: they run first, then the database closes on the
    // thread that opened it.
    QMetaObject::invokeMethod(
        m_worker,
        [state = m_state] {
            state->stopTimers();
            state->sink.close();
            QThread::currentThread()->quit();
        },
        Qt::QueuedConnection);
    m_thread.wait();
    delete m_worker;
}

template <typename Result>
void ResultWriter::post(QObject* context, std::function<Result(State&)> job,
                        std::function<void(const Result&)> answer,
                        std::function<void(const Result&)> here)
{
    ++m_pending;
    QPointer<QObject> to(context);
    QMetaObject::invokeMethod(
        m_worker,
        [this, state = m_state, job = std::move(job), answer = std::move(answer),
         here = std::move(here), to] {
            const Result result = job(*state);
            QMetaObject::invokeMethod(
                this,
                [this, result, answer, here, to] {
                    --m_pending;
                    if (here)
                        here(result);
                    if (!to)
                        return;
                    if (to->thread() == thread())
                        answer(result);
                    else
                        QMetaObject::invokeMethod(
                            to, [result, answer] { answer(result); }, Qt::QueuedConnection);
                },
                Qt::QueuedConnection);
        },
        Qt::QueuedConnection);
}

void ResultWriter::reportWaiting(int waiting, const QString& error)
{
    if (waiting == m_waiting && error == m_waitingError)
        return;
    m_waiting = waiting;
    m_waitingError = error;
    emit waitingChanged(waiting, error);
}

void ResultWriter::open(const QString& url, const QString& station, QObject* context, OpenDone done)
{
    ++m_opening;
    std::function<Opened(State&)> job = [url, station, folder = m_spoolFolder,
                                         worker = m_worker](State& state) {
        Opened opened;
        if (!state.sink.open(url, station, folder, &opened.error))
            return opened;
        opened.ok = true;
        opened.displayText = state.sink.displayText();
        opened.spoolError = state.sink.spoolError();
        opened.spoolPath = state.sink.spoolPath();
        for (const StationLease::Leftover& l : state.sink.takeLeftovers())
            if (l.station == station)
                opened.interrupted.append(l);
        if (!station.isEmpty()) {
            state.startTimers(worker);
            opened.waiting = std::max(0, state.sink.waiting());
            state.spoolChanged(opened.waiting, QString());
        }
        return opened;
    };
    post<Opened>(context, std::move(job), std::move(done), [this](const Opened& o) {
        --m_opening;
        if (o.ok) {
            m_open = true;
            m_displayText = o.displayText;
            m_spoolPath = o.spoolPath;
        }
    });
}

ResultWriter::Opened ResultWriter::openAndWait(const QString& url, const QString& station)
{
    Opened result;
    QEventLoop loop;
    open(url, station, &loop, [&](const Opened& o) {
        result = o;
        loop.quit();
    });
    loop.exec();
    return result;
}

void ResultWriter::run(QObject* context, std::function<void(ResultDatabase* db)> job,
                       std::function<void()> done)
{
    std::function<bool(State&)> work = [job = std::move(job)](State& state) {
        job(state.sink.database());
        return true;
    };
    post<bool>(context, std::move(work), [done = std::move(done)](const bool&) { done(); });
}

void ResultWriter::beginUnit(const UnitRecord& record, QObject* context, BeginDone done)
{
    using Begun = std::pair<UnitRecord, Saved>;
    std::function<Begun(State&)> job = [record](State& state) {
        Begun begun{record, Saved()};
        begun.second = state.sink.begin(begun.first);
        if (begun.second.spooled)
            state.spoolChanged(state.sink.waiting(), begun.second.why);
        return begun;
    };
    post<Begun>(context, std::move(job), [done](const Begun& b) { done(b.first, b.second); });
}

void ResultWriter::finishUnit(const UnitRecord& record, QObject* context, FinishDone done)
{
    std::function<Saved(State&)> job = [record](State& state) {
        const Saved saved = state.sink.finish(record);
        if (saved.spooled)
            state.spoolChanged(state.sink.waiting(), saved.why);
        else if (saved.error.isEmpty())
            state.spoolChanged(std::max(0, state.sink.waiting()), QString());
        return saved;
    };
    post<Saved>(context, std::move(job), std::move(done));
}

void ResultWriter::flushNow()
{
    QMetaObject::invokeMethod(
        m_worker,
        [state = m_state] {
            if (state->retry)
                state->retry->stop();
            state->flush();
        },
        Qt::QueuedConnection);
}

} // namespace opentop
