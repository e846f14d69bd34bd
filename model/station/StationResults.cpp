#include "model/station/StationResults.h"

#include "model/eol/ResultUrl.h"
#include "model/eol/ResultWriter.h"

#include <algorithm>

namespace opentop {

StationResults::StationResults(QObject* parent)
    : QObject(parent)
    , m_writer(std::make_unique<ResultWriter>())
{
    m_retry.setSingleShot(true);
    connect(&m_retry, &QTimer::timeout, this, &StationResults::retryUnsavedNow);
    m_openRetry.setSingleShot(true);
    connect(&m_openRetry, &QTimer::timeout, this, [this] {
        if (!m_writer->isOpen() && !m_writer->isOpening())
            open(m_url);
    });
}

StationResults::~StationResults() = default;

void StationResults::open(const QString& url)
{
    m_url = url;
    m_openRetry.stop();
    m_writer->open(ResultUrl::stationLocation(url), m_station, this,
                   [this](const ResultWriter::Opened& o) {
                       if (o.ok) {
                           m_error.clear();
                           m_openDelayS = 2;
                           if (!o.interrupted.isEmpty())
                               m_interrupted = o.interrupted;
                       } else {
                           m_error = o.error;
                           m_openRetry.start(m_openDelayS * 1000);
                           m_openDelayS = std::min(30, m_openDelayS * 2);
                       }
                       emit opened(o.ok, o.error, o.interrupted);
                   });
}

bool StationResults::openAndWait(const QString& url, QString* error,
                                 QVector<StationLease::Leftover>* interrupted)
{
    const ResultWriter::Opened o =
        m_writer->openAndWait(ResultUrl::stationLocation(url), m_station);
    if (!o.ok && error)
        *error = o.error;
    if (o.ok && !o.interrupted.isEmpty())
        m_interrupted = o.interrupted;
    *interrupted = o.ok ? o.interrupted : QVector<StationLease::Leftover>();
    return o.ok;
}

QString StationResults::text() const
{
    if (m_writer->isOpen())
        return m_writer->displayText();
    if (m_writer->isOpening())
        return tr("opening the results database");
    if (!m_error.isEmpty())
        return tr("NOT REACHABLE (%1); trying again by itself").arg(m_error);
    return tr("no results database");
}

QString StationResults::refusal() const
{
    if (m_unsaved)
        return tr("the result of unit %1 (%2) is not in the results database yet: nothing is "
                  "tested until it is. The station tries again by itself (%3)")
            .arg(m_unsaved->serial, unitStatusName(m_unsaved->status).toUpper(), m_storeError);
    if (m_writer->isOpen())
        return QString();
    return m_writer->isOpening() ? tr("the results database is being opened; try again in a moment")
           : m_error.isEmpty()
               ? tr("the results database is not open; nothing is tested unless it is recorded")
               : tr("the results database cannot be reached (%1); nothing is tested unless it "
                    "is recorded. The station tries again by itself.")
                     .arg(m_error);
}

bool StationResults::unitEnded(const UnitRecord& record, const QString& storeError, bool spooled)
{
    m_storeError = storeError;
    m_lastSpooled = spooled;
    // A verdict the database does not hold is not a result yet: kept and tried again. (A unit
    // never begun sent nothing: nothing to keep.)
    if (m_storeError.isEmpty() || record.id.isEmpty())
        return true;
    m_unsaved = record;
    m_retryDelayS = 1;
    scheduleRetry();
    return false;
}

int StationResults::waiting() const
{
    return m_writer->waiting();
}

QString StationResults::waitingError() const
{
    return m_writer->waitingError();
}

void StationResults::sendWaitingNow()
{
    m_writer->flushNow();
}

int StationResults::nextRetrySeconds() const
{
    return m_retry.isActive() ? (m_retry.remainingTime() + 999) / 1000 : 0;
}

void StationResults::scheduleRetry()
{
    m_retry.start(m_retryDelayS * 1000);
    m_retryDelayS = std::min(30, m_retryDelayS * 2);
}

void StationResults::retryUnsavedNow()
{
    if (!m_unsaved)
        return;
    m_retry.stop();
    m_writer->finishUnit(*m_unsaved, this, [this](const ResultWriter::Saved& saved) {
        if (!m_unsaved)
            return;
        if (!saved.error.isEmpty()) {
            m_storeError = saved.error;
            scheduleRetry();
            emit unsavedAnswered(false, saved.error);
            return;
        }
        m_lastSpooled = saved.spooled;
        m_unsaved.reset();
        m_storeError.clear();
        emit unsavedAnswered(true, QString());
    });
}

} // namespace opentop
