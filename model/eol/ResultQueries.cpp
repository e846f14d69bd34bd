#include "model/eol/ResultQueries.h"

#include "model/eol/ResultDatabase.h"
#include "model/eol/UnitRecordJson.h"

#include <QSqlError>
#include <QSqlQuery>
#include <QSqlRecord>
#include <algorithm>

namespace opentop {

namespace {

const char* const kUnitColumns =
    "unit_id, serial, station, operator_name, started_utc, ended_utc, recipe_name,"
    " recipe_revision, recipe_checksum, status, failure_reason, %1";

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
    r.attempt = q.value(11).toInt(); // NULL before schema 5: 0
    r.approvalId = q.value(12).toString();
    r.approver = q.value(13).toString();
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

QString ResultQueries::sourceColumns() const
{
    // How a drive's variant was known came with schema 4.
    return database_.schemaVersion() >= 4 ? QStringLiteral("variant_source, variant_proof")
                                          : QStringLiteral("NULL, NULL");
}

QString ResultQueries::unitColumns() const
{
    // Attempt numbers came with schema 5, approvals with 6 (older rows read as unapproved).
    return QString::fromLatin1(kUnitColumns)
               .arg(database_.schemaVersion() >= 5 ? QStringLiteral("attempt")
                                                   : QStringLiteral("NULL")) +
           (database_.schemaVersion() >= 6 ? QStringLiteral(", approval_id, approver")
                                           : QStringLiteral(", NULL, NULL"));
}

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

UnitDrive ResultQueries::driveFrom(const QSqlQuery& q, int first)
{
    UnitDrive d;
    d.machineNumber = q.value(first).toInt();
    d.model = q.value(first + 1).toString();
    d.variant = q.value(first + 2).toString();
    d.firmware = q.value(first + 3).toString();
    // NULL on rows from before schema version 4: nothing was said then.
    d.variantSource =
        variantSourceFromName(q.value(first + 4).toString()).value_or(VariantSource::None);
    d.variantProof = q.value(first + 5).toString();
    return d;
}

bool ResultQueries::addDrives(QVector<UnitRecord>* units, QString* error) const
{
    QHash<QString, int> index;
    for (int i = 0; i < units->size(); ++i)
        index.insert(units->at(i).id, i);
    const QStringList ids = index.keys();
    QSqlQuery q(database_.db());
    q.setForwardOnly(true);
    constexpr int kChunk = 500; // well under every engine's limit of bound values
    for (int from = 0; from < ids.size(); from += kChunk) {
        const QStringList chunk = ids.mid(from, kChunk);
        QStringList marks;
        for (int i = 0; i < chunk.size(); ++i)
            marks << QStringLiteral("?");
        q.prepare(QStringLiteral("SELECT unit_id, machine_number, model, variant, firmware,"
                                 " %2 FROM unit_drives"
                                 " WHERE unit_id IN (%1) ORDER BY unit_id, drive_index")
                      .arg(marks.join(QStringLiteral(", ")), sourceColumns()));
        for (const QString& id : chunk)
            q.addBindValue(id);
        if (!q.exec()) {
            fail(q, error);
            return false;
        }
        while (q.next())
            (*units)[index.value(q.value(0).toString())].drives.append(driveFrom(q, 1));
    }
    return true;
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
    if (!f.checksum.isEmpty())
        add("recipe_checksum = ?", f.checksum);
    if (f.status)
        add("status = ?", unitStatusName(*f.status));
    if (!f.station.isEmpty())
        add("station = ?", f.station);
    QString sql = QStringLiteral("SELECT %1 FROM units").arg(unitColumns());
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
    q.prepare(QStringLiteral("SELECT %1 FROM units WHERE unit_id = ?").arg(unitColumns()));
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
    const QByteArray drives = QStringLiteral("SELECT machine_number, model, variant, firmware,"
                                             " %1 FROM unit_drives WHERE unit_id = ?"
                                             " ORDER BY drive_index")
                                  .arg(sourceColumns())
                                  .toLatin1();
    if (!select(drives.constData())) {
        fail(q, error);
        return std::nullopt;
    }
    while (q.next())
        r.drives.append(driveFrom(q, 0));
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

std::optional<YieldReport::Earlier> ResultQueries::testedBefore(const ResultFilter& f,
                                                                QString* error) const
{
    YieldReport::Earlier earlier;
    if (!f.from.isValid())
        return earlier;
    // The verdicts before the range of each (checksum, serial) the range (as find() selects
    // it) has a unit of.
    QString sql =
        QStringLiteral("SELECT e.recipe_checksum, e.serial, COUNT(*),"
                       " SUM(CASE WHEN e.status = 'pass' THEN 1 ELSE 0 END) FROM units e"
                       " WHERE e.started_utc < ? AND e.status IN ('pass', 'fail')"
                       " AND EXISTS (SELECT 1 FROM units r WHERE r.serial = e.serial"
                       " AND r.recipe_checksum = e.recipe_checksum AND r.started_utc >= ?");
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
    if (!f.checksum.isEmpty())
        add(" AND r.recipe_checksum = ?", f.checksum);
    if (f.status)
        add(" AND r.status = ?", unitStatusName(*f.status));
    if (!f.station.isEmpty())
        add(" AND r.station = ?", f.station);
    sql += QStringLiteral(") GROUP BY e.recipe_checksum, e.serial");
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
        earlier.insert({q.value(0).toString(), q.value(1).toString()},
                       {q.value(2).toInt(), q.value(3).toInt() > 0});
    return earlier;
}

std::optional<ResultQueries::SerialHistory>
ResultQueries::serialHistory(const QString& serial, const QString& checksum, QString* error) const
{
    QSqlQuery q(database_.db());
    q.setForwardOnly(true);
    q.prepare(QStringLiteral("SELECT unit_id, status, recipe_checksum FROM units WHERE serial = ?"
                             " AND status IN ('pass', 'fail') ORDER BY started_utc, unit_id"));
    q.addBindValue(serial);
    if (!q.exec()) {
        fail(q, error);
        return std::nullopt;
    }
    SerialHistory h;
    while (q.next()) {
        const bool pass = q.value(1).toString() == QLatin1String("pass");
        if (q.value(2).toString() == checksum) {
            ++h.verdicts;
            h.failures += pass ? 0 : 1;
        }
        if (pass) {
            h.passedAny = true;
            h.passedUnits << q.value(0).toString();
        }
    }
    return h;
}

std::optional<QVector<UnitRecord>> ResultQueries::earlierOf(const UnitRecord& record,
                                                            QString* error) const
{
    ResultFilter filter;
    filter.serial = record.serial;
    filter.to = record.started;
    auto units = find(filter, error);
    if (units) // a serial with * or ? is a pattern to find(): only this very serial
        units->erase(std::remove_if(units->begin(), units->end(),
                                    [&record](const UnitRecord& u) {
                                        return u.serial != record.serial || u.id == record.id;
                                    }),
                     units->end());
    return units;
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
