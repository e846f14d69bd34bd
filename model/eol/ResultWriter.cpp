#include "eol/ResultWriter.h"

#include "ModelLog.h"
#include "eol/ResultDatabase.h"
#include "eol/ResultStore.h"
#include "eol/ResultUrl.h"

#include <QDateTime>
#include <QEventLoop>
#include <QPointer>

namespace opentop {

// Touched only on the writer's thread.
struct ResultWriter::State
{
    std::unique_ptr<ResultDatabase> db;
    std::unique_ptr<ResultStore> store;
    QString url; // as opened: a lost server connection is opened again with it

    // A server that went away (restarted, network) leaves the connection dead: QtSql does not
    // reconnect by itself. Opened again without marking anything interrupted (this station's
    // own unit may be in progress).
    bool reconnect(QString* error)
    {
        if (url.isEmpty())
            return false;
        std::unique_ptr<ResultDatabase> fresh = ResultDatabase::open(url, error);
        if (!fresh)
            return false;
        store.reset();
        db = std::move(fresh);
        store = std::make_unique<ResultStore>(*db);
        qCInfo(lcModel) << "results database: connected again to" << db->url().displayText();
        return true;
    }
    // A job's write that failed is tried once more on a new connection, when one can be made.
    template <typename Write> bool withRetry(Write write, QString* error)
    {
        if (store && write(*store, error))
            return true;
        QString why;
        if (!reconnect(&why)) {
            if (error->isEmpty())
                *error = why;
            return false;
        }
        error->clear();
        return write(*store, error);
    }
};

ResultWriter::ResultWriter(QObject* parent)
    : QObject(parent)
    , m_worker(new QObject)
    , m_state(std::make_shared<State>())
{
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
            state->store.reset();
            state->db.reset();
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

void ResultWriter::open(const QString& url, const QString& station, QObject* context, OpenDone done)
{
    ++m_opening;
    std::function<Opened(State&)> job = [url, station](State& state) {
        Opened opened;
        std::unique_ptr<ResultDatabase> db = ResultDatabase::open(url, &opened.error);
        if (!db)
            return opened;
        opened.displayText = db->url().displayText();
        state.store.reset();
        state.db = std::move(db);
        state.url = url;
        state.store = std::make_unique<ResultStore>(*state.db);
        opened.ok = true;
        if (!station.isEmpty()) {
            QString why;
            const int marked =
                state.store->markInterrupted(station, QDateTime::currentDateTimeUtc(), &why);
            if (marked < 0)
                qCWarning(lcModel) << "results database: leftovers not marked" << why;
            opened.interrupted = std::max(0, marked);
        }
        return opened;
    };
    post<Opened>(context, std::move(job), std::move(done), [this](const Opened& o) {
        --m_opening;
        if (o.ok) {
            m_open = true;
            m_displayText = o.displayText;
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
        job(state.db.get());
        return true;
    };
    post<bool>(context, std::move(work), [done = std::move(done)](const bool&) { done(); });
}

void ResultWriter::beginUnit(const UnitRecord& record, QObject* context, BeginDone done)
{
    using Begun = std::pair<UnitRecord, QString>;
    std::function<Begun(State&)> job = [record](State& state) {
        Begun begun{record, QString()};
        if (!state.store && state.url.isEmpty()) {
            begun.second = tr("the results database is not open");
            return begun;
        }
        state.withRetry(
            [&begun](ResultStore& store, QString* error) {
                return store.beginUnit(begun.first, error); // a retry keeps the id it was given
            },
            &begun.second);
        return begun;
    };
    post<Begun>(context, std::move(job), [done](const Begun& b) { done(b.first, b.second); });
}

void ResultWriter::finishUnit(const UnitRecord& record, QObject* context, FinishDone done)
{
    std::function<QString(State&)> job = [record](State& state) {
        QString error;
        if (!state.store && state.url.isEmpty())
            return tr("the results database is not open");
        state.withRetry(
            [&record](ResultStore& store, QString* why) {
                UnitRecord finished = record;
                return store.finishUnit(finished, why);
            },
            &error);
        return error;
    };
    post<QString>(context, std::move(job), std::move(done));
}

} // namespace opentop
