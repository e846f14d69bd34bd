#include "eol/ResultQueries.h"

#include "eol/ResultDatabase.h"
#include "eol/UnitRecordJson.h"

#include <QSqlError>
#include <QSqlQuery>
#include <QSqlRecord>
#include <algorithm>

namespace opentop {

namespace {

const char* const kUnitColumns =
    "unit_id, serial, station, operator_name, started_utc, ended_utc, recipe_name,"
    " recipe_revision, recipe_checksum, status, failure_reason";

// The approval columns exist from schema version 6 on (older databases read as unapproved).
QString unitColumns(const ResultDatabase& db)
{
    return QLatin1String(kUnitColumns) + (db.schemaVersion() >= 6
                                              ? QStringLiteral(", approval_id, approver")
                                              : QStringLiteral(", NULL, NULL"));
}

UnitRecord unitFrom(const QSqlQuery& q)
{
    UnitRecord r;
    r.id = q.value(0).toString();
    r.serial = q.value(1).toString();
    r.station = q.value(2).toString();
    r.operatorName = q.value(3).toString();
    r.started = UnitRecordJson::timeFromText(q.value(4).toString());
    r.ended = UnitRecordJson::timeFromText(q.value(5).toString());
    r.recipeName = q.value(6).toString();
    r.recipeRevision = q.value(7).toString();
    r.recipeChecksum = q.value(8).toString();
    // A status this program does not know is shown as not proven, never as a pass.
    r.status = unitStatusFromName(q.value(9).toString()).value_or(UnitStatus::Interrupted);
    r.failureReason = q.value(10).toString();
    r.approvalId = q.value(11).toString();
    r.approver = q.value(12).toString();
    return r;
}

std::optional<double> optionalNumber(const QVariant& v)
{
    if (v.isNull())
        return std::nullopt;
    return v.toDouble();
}

bool fail(const QSqlQuery& q, QString* error)
{
    if (error)
        *error = q.lastError().text();
    return false;
}

} // namespace

ResultQueries::ResultQueries(ResultDatabase& database)
    : database_(database)
{
}

bool ResultFilter::serialIsPattern() const
{
    return serial.contains(QLatin1Char('*')) || serial.contains(QLatin1Char('?'));
}

QString ResultFilter::serialLike() const
{
    QString like;
    for (const QChar c : serial.toLower()) {
        if (c == QLatin1Char('\\') || c == QLatin1Char('%') || c == QLatin1Char('_'))
            like += QString(QLatin1Char('\\')) + c;
        else if (c == QLatin1Char('*'))
            like += QLatin1Char('%');
        else if (c == QLatin1Char('?'))
            like += QLatin1Char('_');
        else
            like += c;
    }
    return like;
}

std::optional<QVector<UnitRecord>> ResultQueries::find(const ResultFilter& f, QString* error) const
{
    QStringList where;
    QVariantList values;
    auto add = [&](const char* condition, const QVariant& value) {
        where.append(QLatin1String(condition));
        values.append(value);
    };
    // LOWER() on both sides: SQLite's LIKE ignores ASCII case and PostgreSQL's does not.
    if (f.serialIsPattern())
        add("LOWER(serial) LIKE ? ESCAPE '\\'", f.serialLike());
    else if (!f.serial.isEmpty())
        add("serial = ?", f.serial);
    if (f.from.isValid())
        add("started_utc >= ?", UnitRecordJson::timeText(f.from));
    if (f.to.isValid())
        add("started_utc < ?", UnitRecordJson::timeText(f.to));
    if (!f.recipe.isEmpty())
        add("recipe_name = ?", f.recipe);
    if (f.status)
        add("status = ?", unitStatusName(*f.status));
    if (!f.station.isEmpty())
        add("station = ?", f.station);
    QString sql = QStringLiteral("SELECT %1 FROM units").arg(unitColumns(database_));
    if (!where.isEmpty())
        sql += QStringLiteral(" WHERE ") + where.join(QStringLiteral(" AND "));
    // The newest `limit` when limited, returned oldest first like the rest.
    sql += f.limit > 0
               ? QStringLiteral(" ORDER BY started_utc DESC, unit_id DESC LIMIT %1").arg(f.limit)
               : QStringLiteral(" ORDER BY started_utc, unit_id");
    QSqlQuery q(database_.db());
    q.setForwardOnly(true);
    if (!q.prepare(sql)) {
        fail(q, error);
        return std::nullopt;
    }
    for (const QVariant& v : values)
        q.addBindValue(v);
    if (!q.exec()) {
        fail(q, error);
        return std::nullopt;
    }
    QVector<UnitRecord> units;
    while (q.next())
        units.append(unitFrom(q));
    if (f.limit > 0)
        std::reverse(units.begin(), units.end());
    return units;
}

std::optional<UnitRecord> ResultQueries::load(const QString& unitId, QString* error) const
{
    QSqlQuery q(database_.db());
    q.setForwardOnly(true);
    q.prepare(QStringLiteral("SELECT %1 FROM units WHERE unit_id = ?").arg(unitColumns(database_)));
    q.addBindValue(unitId);
    if (!q.exec()) {
        fail(q, error);
        return std::nullopt;
    }
    if (!q.next()) {
        if (error)
            *error = tr("no unit record %1").arg(unitId);
        return std::nullopt;
    }
    UnitRecord r = unitFrom(q);
    auto select = [&](const char* sql) {
        q.prepare(QLatin1String(sql));
        q.addBindValue(unitId);
        return q.exec();
    };
    if (!select("SELECT machine_number, model, variant, firmware FROM unit_drives"
                " WHERE unit_id = ? ORDER BY drive_index")) {
        fail(q, error);
        return std::nullopt;
    }
    while (q.next())
        r.drives.append({q.value(0).toInt(), q.value(1).toString(), q.value(2).toString(),
                         q.value(3).toString()});
    if (!select("SELECT machine_number, parameter, label, value_text, was_written, verified,"
                " read_back FROM written_values WHERE unit_id = ? ORDER BY seq")) {
        fail(q, error);
        return std::nullopt;
    }
    while (q.next())
        r.writtenValues.append({q.value(0).toInt(), q.value(1).toString(), q.value(2).toString(),
                                q.value(3).toString(), q.value(4).toInt() != 0,
                                q.value(5).toInt() != 0, q.value(6).toString()});
    if (!select("SELECT machine_number, step, quantity, measured, unit, lower_limit,"
                " upper_limit, passed FROM measurements WHERE unit_id = ? ORDER BY seq")) {
        fail(q, error);
        return std::nullopt;
    }
    while (q.next()) {
        Measurement m;
        m.machineNumber = q.value(0).toInt();
        m.step = q.value(1).toString();
        m.quantity = q.value(2).toString();
        m.value = q.value(3).toDouble();
        m.unit = q.value(4).toString();
        m.lower = optionalNumber(q.value(5));
        m.upper = optionalNumber(q.value(6));
        m.pass = q.value(7).toInt() != 0;
        r.measurements.append(m);
    }
    if (!select("SELECT line FROM unit_traffic WHERE unit_id = ? ORDER BY seq")) {
        fail(q, error);
        return std::nullopt;
    }
    while (q.next())
        r.traffic.append(q.value(0).toString());
    return r;
}

std::optional<QSet<QPair<QString, QString>>> ResultQueries::testedBefore(const ResultFilter& f,
                                                                         QString* error) const
{
    QSet<QPair<QString, QString>> earlier;
    if (!f.from.isValid())
        return earlier;
    // The units in the range (as find() selects them) that have an earlier record.
    QString sql = QStringLiteral(
        "SELECT DISTINCT r.recipe_name, r.serial FROM units r WHERE r.started_utc >= ?"
        " AND EXISTS (SELECT 1 FROM units e WHERE e.serial = r.serial"
        " AND e.recipe_name = r.recipe_name AND e.started_utc < ?)");
    QVariantList values{UnitRecordJson::timeText(f.from), UnitRecordJson::timeText(f.from)};
    auto add = [&](const char* condition, const QVariant& value) {
        sql += QLatin1String(condition);
        values.append(value);
    };
    if (f.to.isValid())
        add(" AND r.started_utc < ?", UnitRecordJson::timeText(f.to));
    if (f.serialIsPattern())
        add(" AND LOWER(r.serial) LIKE ? ESCAPE '\\'", f.serialLike());
    else if (!f.serial.isEmpty())
        add(" AND r.serial = ?", f.serial);
    if (!f.recipe.isEmpty())
        add(" AND r.recipe_name = ?", f.recipe);
    if (f.status)
        add(" AND r.status = ?", unitStatusName(*f.status));
    if (!f.station.isEmpty())
        add(" AND r.station = ?", f.station);
    QSqlQuery q(database_.db());
    q.setForwardOnly(true);
    q.prepare(sql);
    for (const QVariant& v : values)
        q.addBindValue(v);
    if (!q.exec()) {
        fail(q, error);
        return std::nullopt;
    }
    while (q.next())
        earlier.insert({q.value(0).toString(), q.value(1).toString()});
    return earlier;
}

std::optional<QVector<UnitRecord>> ResultQueries::history(const QString& serial,
                                                          QString* error) const
{
    ResultFilter filter;
    filter.serial = serial;
    const auto units = find(filter, error);
    if (!units)
        return std::nullopt;
    QVector<UnitRecord> whole;
    for (const UnitRecord& unit : *units) {
        const auto record = load(unit.id, error);
        if (!record)
            return std::nullopt;
        whole.append(*record);
    }
    return whole;
}

} // namespace opentop
