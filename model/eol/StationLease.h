#pragma once

#include <QCoreApplication>
#include <QString>
#include <QVector>

namespace opentop {

class ResultDatabase;

// Which 'running' unit belongs to a process that is still alive (docs/eol-results.md). Each
// process that records units takes a lease in the results database (a random id, its station,
// host and process id) and renews it every kRenewS seconds. A running unit is a leftover, to be
// marked interrupted, when its lease is gone, has not been renewed for kLifetimeS seconds by the
// database's own clock, or names a process of this host that no longer exists. So the command
// line and the window on one PC, or two stations given one name, never mark each other's units.
class StationLease
{
    Q_DECLARE_TR_FUNCTIONS(opentop::StationLease)
public:
    static constexpr int kRenewS = 15;
    static constexpr int kLifetimeS = 90;

    struct Leftover
    {
        QString unitId;
        QString serial;
        QString station;
        QString started; // UTC text, as the database keeps it
    };

    // A new lease id for this process and `station`; nothing is written yet.
    StationLease(const QString& station, const QString& program);

    QString id() const { return m_id; }
    QString station() const { return m_station; }

    // Writes the lease (take) or its heartbeat (renew, which takes it again when it was swept
    // while the database was out of reach); end() removes it when the process closes cleanly.
    bool renew(ResultDatabase& db, QString* error);
    bool end(ResultDatabase& db, QString* error);
    // Marks every leftover interrupted, and forgets dead leases; returns them (false on an
    // error). A unit of this lease is never one.
    bool sweep(ResultDatabase& db, QVector<Leftover>* leftovers, QString* error);

    // Whether process `pid` of this host exists (a lease of this host is judged at once).
    static bool processAlive(qint64 pid);
    static QString hostName();

private:
    QString m_id;
    QString m_station;
    QString m_program;
};

} // namespace opentop
