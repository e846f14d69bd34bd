#pragma once

#include "model/eol/StationLease.h"
#include "model/eol/UnitRecord.h"

#include <QObject>
#include <QTimer>
#include <memory>
#include <optional>

namespace opentop {

class ResultWriter;

// Where an operator screen's unit records go: the station's results database on a thread of its
// own (ResultWriter; `url` empty: OPENTOP_EOL_DB, else the default file, made when missing). A
// database that cannot be opened (a server down) is tried again by itself, 2, 4 … 30 s apart,
// until it opens: a line does not wait for someone to restart it. A unit's verdict the database
// did not take is kept and sent again by itself, 1, 2, 4 … 30 s apart; meanwhile, and while the
// database is not open, no unit is tested (refusal()): nothing is tested unless it is recorded.
// (ResultWriter stays out of this header: those who include it need no Qt Sql.)
class StationResults : public QObject
{
    Q_OBJECT
public:
    explicit StationResults(QObject* parent = nullptr);
    ~StationResults() override;

    ResultWriter* writer() const { return m_writer.get(); }
    // The station's name in its lease and records, for the next open.
    void setStation(const QString& station) { m_station = station; }
    // opened() answers, each try again included.
    void open(const QString& url);
    // The same, waiting for the answer in a local event loop; no opened(), no tries again.
    // False with *error; *interrupted: the leftovers this open found.
    bool openAndWait(const QString& url, QString* error,
                     QVector<StationLease::Leftover>* interrupted);
    QString url() const { return m_url; }     // as given to open()
    QString error() const { return m_error; } // why the last try failed; empty once open
    QString text() const;                     // the database for the screen, or why none
    // Units of this station that a process now gone left running, found as it opened:
    // interrupted in the database, and named on the screen.
    const QVector<StationLease::Leftover>& interrupted() const { return m_interrupted; }
    // Why no unit may be tested now (a verdict not recorded, the database not open); empty: it
    // may.
    QString refusal() const;

    // A unit began: its verdict has no store error yet.
    void unitBegun() { m_storeError.clear(); }
    // The verdict as its run left it (EolRun::storeError, EolRun::spooled); false when the
    // database did not take a record it had begun: kept, and sent again by itself.
    bool unitEnded(const UnitRecord& record, const QString& storeError, bool spooled);
    QString storeError() const { return m_storeError; }
    bool lastSpooled() const { return m_lastSpooled; } // kept in the spool, not in the database
    const std::optional<UnitRecord>& unsaved() const { return m_unsaved; }
    int nextRetrySeconds() const;
    void retryUnsavedNow();
    // Records in the spool, waiting for the results database, and why; sent now.
    int waiting() const;
    QString waitingError() const;
    void sendWaitingNow();

signals:
    // An answer to open(): `error` names the database and why not; `interrupted`: the
    // leftovers this open found.
    void opened(bool ok, const QString& error,
                const QVector<opentop::StationLease::Leftover>& interrupted);
    // The unsaved verdict was recorded at last (`recorded`), or another try failed.
    void unsavedAnswered(bool recorded, const QString& error);

private:
    void scheduleRetry();

    std::unique_ptr<ResultWriter> m_writer;
    QString m_station;
    QString m_url;
    QString m_error;
    QTimer m_openRetry;
    int m_openDelayS = 2;
    QVector<StationLease::Leftover> m_interrupted;
    QString m_storeError;
    bool m_lastSpooled = false;
    std::optional<UnitRecord> m_unsaved;
    QTimer m_retry;
    int m_retryDelayS = 1;
};

} // namespace opentop
