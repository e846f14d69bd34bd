#include "model/eol/StationLease.h"

#include "model/ModelLog.h"
#include "model/eol/ResultDatabase.h"
#include "model/eol/ResultStore.h"
#include "model/eol/UnitRecordJson.h"

#include <QCoreApplication>
#include <QSqlError>
#include <QSqlQuery>
#include <QSysInfo>
#include <QUuid>

#ifdef Q_OS_WIN
#include <windows.h>
#else
#include <cerrno>
#include <csignal>
#endif

namespace opentop {

StationLease::StationLease(const QString& station, const QString& program)
    : m_id(QUuid::createUuid().toString(QUuid::WithoutBraces))
    , m_station(station)
    , m_program(program)
{
}

QString StationLease::hostName()
{
    return QSysInfo::machineHostName();
}

bool StationLease::processAlive(qint64 pid)
{
    if (pid <= 0)
        return false;
#ifdef Q_OS_WIN
    HANDLE process = OpenProcess(PROCESS_QUERY_LIMITED_INFORMATION, FALSE, DWORD(pid));
    if (!process)
        return GetLastError() == ERROR_ACCESS_DENIED; // exists, another user's
    DWORD code = 0;
    const bool running = GetExitCodeProcess(process, &code) && code == STILL_ACTIVE;
    CloseHandle(process);
    return running;
#else
    return ::kill(pid_t(pid), 0) == 0 || errno == EPERM;
#endif
}

bool StationLease::renew(ResultDatabase& db, QString* error)
{
    QSqlQuery q(db.db());
    q.prepare(QStringLiteral("UPDATE station_leases SET heartbeat_s = %1 WHERE lease_id = ?")
                  .arg(db.nowSecondsSql()));
    q.addBindValue(m_id);
    if (!ResultDatabase::run(q, error))
        return false;
    if (q.numRowsAffected() == 1)
        return true;
    // Not there yet, or swept while this process could not reach the database: taken (again).
    QSqlQuery take(db.db());
    take.prepare(QStringLiteral("INSERT INTO station_leases (lease_id, station, host, pid, "
                                "program, started_utc, heartbeat_s) VALUES (?, ?, ?, ?, ?, ?, %1)")
                     .arg(db.nowSecondsSql()));
    take.addBindValue(m_id);
    take.addBindValue(m_station);
    take.addBindValue(hostName());
    take.addBindValue(QCoreApplication::applicationPid());
    take.addBindValue(m_program);
    take.addBindValue(UnitRecordJson::timeText(QDateTime::currentDateTimeUtc()));
    return ResultDatabase::run(take, error);
}

bool StationLease::end(ResultDatabase& db, QString* error)
{
    QSqlQuery q(db.db());
    q.prepare(QStringLiteral("DELETE FROM station_leases WHERE lease_id = ?"));
    q.addBindValue(m_id);
    return ResultDatabase::run(q, error);
}

bool StationLease::sweep(ResultDatabase& db, QVector<Leftover>* leftovers, QString* error)
{
    if (!db.begin(error))
        return false;
    auto fail = [&] {
        db.rollback();
        return false;
    };
    const QString host = hostName();
    QSet<QString> dead;
    {
        QSqlQuery q(db.db());
        q.prepare(QStringLiteral("SELECT lease_id, host, pid, heartbeat_s < %1 - %2"
                                 " FROM station_leases WHERE lease_id <> ?")
                      .arg(db.nowSecondsSql())
                      .arg(kLifetimeS));
        q.addBindValue(m_id);
        if (!ResultDatabase::run(q, error))
            return fail();
        while (q.next()) {
            const bool stale = q.value(3).toInt() != 0;
            const bool gone =
                q.value(1).toString() == host && !processAlive(q.value(2).toLongLong());
            if (stale || gone)
                dead.insert(q.value(0).toString());
        }
    }
    QSet<QString> live;
    {
        QSqlQuery q(db.db());
        if (!q.exec(QStringLiteral("SELECT lease_id FROM station_leases"))) {
            if (error)
                *error = q.lastError().text();
            return fail();
        }
        while (q.next())
            live.insert(q.value(0).toString());
    }
    QVector<Leftover> found;
    {
        QSqlQuery q(db.db());
        q.prepare(QStringLiteral("SELECT unit_id, serial, station, started_utc, lease_id"
                                 " FROM units WHERE status = 'running' AND lease_id IS NOT NULL"
                                 " AND lease_id <> ?"));
        q.addBindValue(m_id);
        if (!ResultDatabase::run(q, error))
            return fail();
        while (q.next()) {
            const QString lease = q.value(4).toString();
            if (dead.contains(lease) || !live.contains(lease))
                found.append({q.value(0).toString(), q.value(1).toString(), q.value(2).toString(),
                              q.value(3).toString()});
        }
    }
    for (const Leftover& l : found) {
        QSqlQuery q(db.db());
        q.prepare(QStringLiteral("UPDATE units SET status = 'interrupted', failure_reason = ?"
                                 " WHERE unit_id = ? AND status = 'running'"));
        q.addBindValue(ResultStore::interruptedReason());
        q.addBindValue(l.unitId);
        if (!ResultDatabase::run(q, error))
            return fail();
    }
    for (const QString& lease : dead) {
        QSqlQuery q(db.db());
        q.prepare(QStringLiteral("DELETE FROM station_leases WHERE lease_id = ?"));
        q.addBindValue(lease);
        if (!ResultDatabase::run(q, error))
            return fail();
    }
    if (!db.commit(error))
        return fail();
    for (const Leftover& l : found)
        qCInfo(lcModel) << "results database: unit" << l.serial << "of station" << l.station
                        << "marked interrupted (its process is gone)";
    if (leftovers)
        *leftovers = found;
    return true;
}

} // namespace opentop
