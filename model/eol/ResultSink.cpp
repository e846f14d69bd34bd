#include "model/eol/ResultSink.h"

#include "model/ModelLog.h"
#include "model/eol/ResultDatabase.h"
#include "model/eol/ResultStore.h"

#include <QCoreApplication>

namespace opentop {

namespace {

bool finalStatus(const QString& status)
{
    return status == QLatin1String("pass") || status == QLatin1String("fail") ||
           status == QLatin1String("aborted");
}

} // namespace

ResultSink::ResultSink() = default;

ResultSink::~ResultSink()
{
    close();
}

QString ResultSink::displayText() const
{
    return m_db ? m_db->url().displayText() : QString();
}

bool ResultSink::open(const QString& url, const QString& station, const QString& spoolFolder,
                      QString* error)
{
    std::unique_ptr<ResultDatabase> db = ResultDatabase::open(url, error);
    if (!db)
        return false;
    close();
    m_url = url;
    m_db = std::move(db);
    m_store = std::make_unique<ResultStore>(*m_db);
    if (station.isEmpty())
        return true; // a reader (the results browser): no lease, no spool
    m_lease.emplace(station, QCoreApplication::applicationName());
    m_store->setLease(m_lease->id());
    QString why;
    if (!m_lease->renew(*m_db, &why))
        qCWarning(lcModel) << "results database: lease not taken" << why;
    m_spool = ResultSpool::open(spoolFolder, url, &m_spoolError);
    if (!m_spool)
        qCWarning(lcModel) << m_spoolError;
    // What a station before this one kept goes first; then its units still running are found.
    const Flushed sent = flush();
    if (sent.waiting > 0)
        qCWarning(lcModel) << "results spool:" << sent.waiting << "entries still waiting"
                           << sent.error;
    heartbeat();
    // Rows from before leases (older programs) are judged by the station's name.
    const int legacy = m_store->markInterrupted(station, QDateTime::currentDateTimeUtc(), &why);
    if (legacy > 0)
        qCInfo(lcModel) << "results database:" << legacy
                        << "unit(s) from before leases interrupted";
    return true;
}

void ResultSink::close()
{
    if (m_db && m_lease) {
        QString why;
        if (!m_lease->end(*m_db, &why))
            qCInfo(lcModel) << "results database: lease not ended" << why;
    }
    m_store.reset();
    m_db.reset();
    m_spool.reset();
    m_lease.reset();
}

QVector<StationLease::Leftover> ResultSink::takeLeftovers()
{
    return std::exchange(m_leftovers, {});
}

bool ResultSink::reconnect(QString* error)
{
    if (m_url.isEmpty())
        return false;
    std::unique_ptr<ResultDatabase> fresh = ResultDatabase::open(m_url, error);
    if (!fresh)
        return false;
    m_store.reset();
    m_db = std::move(fresh);
    m_store = std::make_unique<ResultStore>(*m_db);
    if (m_lease) {
        m_store->setLease(m_lease->id());
        QString why;
        if (!m_lease->renew(*m_db, &why)) // before any unit of it arrives: never a leftover
            qCWarning(lcModel) << "results database: lease not renewed" << why;
    }
    qCInfo(lcModel) << "results database: connected again to" << m_db->url().displayText();
    return true;
}

template <typename Write> ResultSink::Outcome ResultSink::write(Write write, QString* error)
{
    if (m_store && write(*m_store, error))
        return Outcome::Done;
    // A server that went away (restarted, network) leaves the connection dead: QtSql does not
    // reconnect by itself. A write that fails on a new connection too was refused.
    QString why;
    if (!reconnect(&why)) {
        if (error->isEmpty())
            *error = why;
        return Outcome::Unreachable;
    }
    error->clear();
    return write(*m_store, error) ? Outcome::Done : Outcome::Refused;
}

ResultSink::Saved ResultSink::begin(UnitRecord& record)
{
    ResultStore::identify(record); // the spool keeps the id the database will have
    return save(ResultSpool::Kind::Begin, record);
}

ResultSink::Saved ResultSink::finish(const UnitRecord& record)
{
    UnitRecord copy = record;
    return save(ResultSpool::Kind::Finish, copy);
}

ResultSink::Saved ResultSink::save(ResultSpool::Kind kind, UnitRecord& record)
{
    Saved saved;
    if (!m_store && m_url.isEmpty()) {
        saved.error = tr("the results database is not open");
        return saved;
    }
    // Older entries first: a record never overtakes one the spool holds.
    const Flushed before = m_spool ? flush() : Flushed();
    const bool queued = before.waiting != 0;
    if (queued)
        saved.error = before.error;
    else {
        const Outcome o = write(
            [&](ResultStore& store, QString* why) {
                // A begin learns its attempt number from the database.
                UnitRecord r = record;
                const bool ok = kind == ResultSpool::Kind::Begin ? store.beginUnit(r, why)
                                                                 : store.finishUnit(r, why);
                if (ok)
                    record.attempt = r.attempt;
                return ok;
            },
            &saved.error);
        if (o == Outcome::Done || o == Outcome::Refused || !m_spool)
            return saved;
    }
    QString why;
    if (!m_spool->append(kind, record, m_lease ? m_lease->id() : QString(), &why)) {
        saved.error = saved.error.isEmpty() ? why : saved.error + QStringLiteral("; ") + why;
        return saved;
    }
    saved.why = saved.error;
    saved.error.clear();
    saved.spooled = true;
    return saved;
}

ResultSink::Outcome ResultSink::deliver(const ResultSpool::Entry& entry, QString* error)
{
    return write(
        [&](ResultStore& store, QString* why) {
            // Sent before and the removal from the spool lost (a kill in between): done.
            const QString status = store.statusOf(entry.record.id, why);
            if (!why->isEmpty())
                return false;
            if (entry.kind == ResultSpool::Kind::Begin && !status.isEmpty())
                return true;
            if (entry.kind == ResultSpool::Kind::Finish && finalStatus(status))
                return true;
            // The unit belongs to the lease that tested it (this process's, or a gone one's).
            store.setLease(entry.lease);
            UnitRecord r = entry.record;
            const bool ok = entry.kind == ResultSpool::Kind::Begin ? store.beginUnit(r, why)
                                                                   : store.finishUnit(r, why);
            store.setLease(m_lease ? m_lease->id() : QString());
            return ok;
        },
        error);
}

ResultSink::Flushed ResultSink::flush()
{
    Flushed f;
    if (!m_spool)
        return f;
    for (;;) {
        QString why;
        const std::optional<ResultSpool::Entry> entry = m_spool->oldest(&why);
        if (!entry) {
            if (!why.isEmpty())
                f.error = why;
            break;
        }
        const Outcome o = deliver(*entry, &why);
        if (o != Outcome::Done) {
            f.error = o == Outcome::Refused
                          ? tr("the results database refuses unit %1 (serial %2): %3")
                                .arg(entry->record.id, entry->record.serial, why)
                          : why;
            break;
        }
        if (!m_spool->remove(entry->seq, &why)) {
            f.error = why;
            break;
        }
        ++f.sent;
    }
    if (f.sent)
        qCInfo(lcModel) << "results spool: sent" << f.sent << "entries to the database";
    f.waiting = m_spool->count();
    return f;
}

int ResultSink::waiting()
{
    return m_spool ? m_spool->count() : 0;
}

void ResultSink::heartbeat()
{
    if (!m_lease)
        return;
    QString why;
    if (!m_db || !m_lease->renew(*m_db, &why)) {
        if (!reconnect(&why))
            return; // out of reach: the spool keeps what comes meanwhile
    }
    QVector<StationLease::Leftover> found;
    if (!m_lease->sweep(*m_db, &found, &why)) {
        qCWarning(lcModel) << "results database: leftovers not swept" << why;
        return;
    }
    m_leftovers += found;
}

} // namespace opentop
