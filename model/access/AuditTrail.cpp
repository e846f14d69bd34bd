#include "model/access/AuditTrail.h"

#include "model/ModelLog.h"
#include "model/eol/ResultDatabase.h"

#include <QSqlError>
#include <QSqlQuery>
#include <QTimeZone>
#include <QUuid>
#include <cmath>

namespace opentop {

AuditTrail::AuditTrail(ResultDatabase& database)
    : database_(database)
{
}

bool AuditTrail::record(const QString& station, const QString& user, const QString& action,
                        const QString& detail, QString* error)
{
    QSqlQuery q(database_.db());
    // The database's clock: the trail of several stations reads in one order.
    q.prepare(QStringLiteral("INSERT INTO audit (audit_id, at_s, station, user_name, action, "
                             "detail) VALUES (?, %1, ?, ?, ?, ?)")
                  .arg(database_.nowSecondsSql()));
    q.addBindValue(QUuid::createUuid().toString(QUuid::WithoutBraces));
    q.addBindValue(station.isNull() ? QString(QLatin1String("")) : station);
    q.addBindValue(user.isNull() ? QString(QLatin1String("")) : user);
    q.addBindValue(action);
    q.addBindValue(detail.isNull() ? QString(QLatin1String("")) : detail);
    if (q.exec())
        return true;
    qCWarning(lcModel) << "audit trail: not recorded:" << action << q.lastError().text();
    if (error)
        *error = q.lastError().text();
    return false;
}

std::optional<QVector<AuditEntry>> AuditTrail::query(const AuditFilter& f, QString* error)
{
    QStringList where;
    QVariantList values;
    if (f.since.isValid()) {
        where << QStringLiteral("at_s >= ?");
        values << f.since.toMSecsSinceEpoch() / 1000.0;
    }
    if (!f.user.isEmpty()) {
        where << QStringLiteral("user_name = ?");
        values << f.user;
    }
    if (!f.station.isEmpty()) {
        where << QStringLiteral("station = ?");
        values << f.station;
    }
    QSqlQuery q(database_.db());
    // The newest `limit` entries, returned oldest first.
    q.prepare(QStringLiteral("SELECT at_s, station, user_name, action, detail FROM audit%1"
                             " ORDER BY at_s DESC, audit_id DESC LIMIT %2")
                  .arg(where.isEmpty()
                           ? QString()
                           : QStringLiteral(" WHERE ") + where.join(QStringLiteral(" AND ")))
                  .arg(f.limit));
    for (const QVariant& v : values)
        q.addBindValue(v);
    if (!q.exec()) {
        if (error)
            *error = q.lastError().text();
        return std::nullopt;
    }
    QVector<AuditEntry> entries;
    while (q.next()) {
        AuditEntry e;
        e.time = QDateTime::fromMSecsSinceEpoch(qint64(std::llround(q.value(0).toDouble() * 1000)),
                                                QTimeZone::utc());
        e.station = q.value(1).toString();
        e.user = q.value(2).toString();
        e.action = q.value(3).toString();
        e.detail = q.value(4).toString();
        entries.prepend(e);
    }
    return entries;
}

} // namespace opentop
