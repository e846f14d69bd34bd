#include "model/eol/ResultStore.h"

#include "model/eol/ResultDatabase.h"
#include "model/eol/UnitRecordJson.h"

#include <QSqlError>
#include <QSqlQuery>
#include <QTimeZone>
#include <QUuid>
#include <algorithm>
#include <atomic>

namespace opentop {

namespace {

QVariant numberOrNull(const std::optional<double>& value)
{
    return value ? QVariant(*value) : QVariant(QMetaType::fromType<double>());
}

// Binds the values; a null QString is bound as '' (the text columns are NOT NULL, and QtSql binds
// a null QString as NULL).
void bind(QSqlQuery& query, std::initializer_list<QVariant> values)
{
    for (const QVariant& v : values) {
        if (v.typeId() == QMetaType::QString && v.toString().isNull())
            query.addBindValue(QString(QLatin1String("")));
        else
            query.addBindValue(v);
    }
}

QDateTime nowUtc()
{
    // Milliseconds are what the database keeps: the record in memory is what it reads back.
    return UnitRecordJson::timeFromText(UnitRecordJson::timeText(QDateTime::currentDateTimeUtc()));
}

// A unit's start decides which record of a serial came first (first-pass yield), and the ids
// are random: two units begun in one millisecond would be ordered by chance. Starts this
// process records are therefore strictly increasing, at most a few milliseconds late.
QDateTime uniqueStartUtc()
{
    static std::atomic<qint64> last{0};
    const qint64 now = nowUtc().toMSecsSinceEpoch();
    qint64 previous = last.load();
    qint64 next = 0;
    do {
        next = std::max(now, previous + 1);
    } while (!last.compare_exchange_weak(previous, next));
    return QDateTime::fromMSecsSinceEpoch(next, QTimeZone::utc());
}

} // namespace

ResultStore::ResultStore(ResultDatabase& database)
    : database_(database)
{
}

QString ResultStore::interruptedReason()
{
    return tr("interrupted: the station stopped before the unit was finished (killed, power "
              "lost or crashed); the unit was not proven");
}

bool ResultStore::beginUnit(UnitRecord& record, QString* error)
{
    if (record.serial.isEmpty()) {
        if (error)
            *error = tr("a unit needs a serial number");
        return false;
    }
    identify(record);
    if (!database_.begin(error))
        return false;
    QSqlQuery q(database_.db());
    const bool leases = hasLeases();
    const bool attempts = hasAttempts();
    if (attempts) {
        // Counted in the transaction that inserts the row: a spooled unit sent later is
        // numbered after the verdicts recorded before it, as it was tested.
        q.prepare(QStringLiteral("SELECT COUNT(*) FROM units WHERE serial = ? AND"
                                 " recipe_checksum = ? AND status IN ('pass', 'fail')"));
        bind(q, {record.serial, record.recipeChecksum});
        if (!ResultDatabase::run(q, error) || !q.next()) {
            database_.rollback();
            return false;
        }
        record.attempt = q.value(0).toInt() + 1;
        q.finish();
    }
    const bool approvals = database_.schemaVersion() >= 6;
    // Columns of later schema versions, where the database has them.
    QString columns;
    QString marks;
    const auto add = [&](bool has, const char* names, const char* places) {
        if (has) {
            columns += QLatin1String(names);
            marks += QLatin1String(places);
        }
    };
    add(leases, ", lease_id", ", ?");
    add(attempts, ", attempt", ", ?");
    add(approvals, ", approval_id, approver", ", ?, ?");
    q.prepare(QStringLiteral("INSERT INTO units (unit_id, serial, station, operator_name, "
                             "started_utc, ended_utc, recipe_name, recipe_revision, "
                             "recipe_checksum, status, failure_reason%1) VALUES (?, ?, ?, ?, ?, "
                             "NULL, ?, ?, ?, 'running', ''%2)")
                  .arg(columns, marks));
    bind(q, {record.id, record.serial, record.station, record.operatorName,
             UnitRecordJson::timeText(record.started), record.recipeName, record.recipeRevision,
             record.recipeChecksum});
    const QVariant none(QMetaType::fromType<QString>());
    if (leases)
        q.addBindValue(lease_.isEmpty() ? none : QVariant(lease_));
    if (attempts)
        q.addBindValue(record.attempt);
    if (approvals) {
        q.addBindValue(record.approvalId.isEmpty() ? none : QVariant(record.approvalId));
        q.addBindValue(record.approver.isEmpty() ? none : QVariant(record.approver));
    }
    if (!ResultDatabase::run(q, error) || !database_.commit(error)) {
        database_.rollback();
        return false;
    }
    return true;
}

bool ResultStore::writeChildren(const UnitRecord& r, QString* error)
{
    QSqlQuery q(database_.db());
    // A finish that is repeated after a failed commit starts from no children again.
    for (const char* table : {"unit_drives", "written_values", "measurements", "unit_traffic"}) {
        q.prepare(QStringLiteral("DELETE FROM %1 WHERE unit_id = ?").arg(QLatin1String(table)));
        q.addBindValue(r.id);
        if (!ResultDatabase::run(q, error))
            return false;
    }
    // How a variant was known came with schema 4.
    const bool sources = database_.schemaVersion() >= 4;
    q.prepare(sources ? QStringLiteral("INSERT INTO unit_drives (unit_id, drive_index,"
                                       " machine_number, model, variant, firmware, variant_source,"
                                       " variant_proof) VALUES (?, ?, ?, ?, ?, ?, ?, ?)")
                      : QStringLiteral("INSERT INTO unit_drives (unit_id, drive_index,"
                                       " machine_number, model, variant, firmware)"
                                       " VALUES (?, ?, ?, ?, ?, ?)"));
    for (int i = 0; i < r.drives.size(); ++i) {
        const UnitDrive& d = r.drives[i];
        QVariantList values{QVariant(r.id),    QVariant(i),         QVariant(d.machineNumber),
                            QVariant(d.model), QVariant(d.variant), QVariant(d.firmware)};
        if (sources)
            values << QVariant(variantSourceName(d.variantSource)) << QVariant(d.variantProof);
        for (const QVariant& v : values) // as bind() does: a null text is an empty one
            q.addBindValue(v.typeId() == QMetaType::QString && v.toString().isNull()
                               ? QVariant(QString(QLatin1String("")))
                               : v);
        if (!ResultDatabase::run(q, error))
            return false;
    }
    q.prepare(QStringLiteral(
        "INSERT INTO written_values (unit_id, seq, machine_number, parameter, label, value_text,"
        " was_written, verified, read_back) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)"));
    for (int i = 0; i < r.writtenValues.size(); ++i) {
        const WrittenValue& w = r.writtenValues[i];
        bind(q, {QVariant(r.id), QVariant(i), QVariant(w.machineNumber), QVariant(w.parameter),
                 QVariant(w.label), QVariant(w.value), QVariant(w.written ? 1 : 0),
                 QVariant(w.verified ? 1 : 0), QVariant(w.readBack)});
        if (!ResultDatabase::run(q, error))
            return false;
    }
    q.prepare(QStringLiteral(
        "INSERT INTO measurements (unit_id, seq, machine_number, step, quantity, measured, unit,"
        " lower_limit, upper_limit, passed) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?)"));
    for (int i = 0; i < r.measurements.size(); ++i) {
        const Measurement& m = r.measurements[i];
        bind(q, {QVariant(r.id), QVariant(i), QVariant(m.machineNumber), QVariant(m.step),
                 QVariant(m.quantity), QVariant(m.value), QVariant(m.unit), numberOrNull(m.lower),
                 numberOrNull(m.upper), QVariant(m.pass ? 1 : 0)});
        if (!ResultDatabase::run(q, error))
            return false;
    }
    q.prepare(QStringLiteral("INSERT INTO unit_traffic (unit_id, seq, line) VALUES (?, ?, ?)"));
    for (int i = 0; i < r.traffic.size(); ++i) {
        bind(q, {QVariant(r.id), QVariant(i), QVariant(r.traffic[i])});
        if (!ResultDatabase::run(q, error))
            return false;
    }
    return true;
}

bool ResultStore::finishUnit(UnitRecord& record, QString* error)
{
    if (record.status == UnitStatus::Running || record.status == UnitStatus::Interrupted) {
        if (error)
            *error = tr("a unit is finished with pass, fail, error or aborted, not %1")
                         .arg(unitStatusName(record.status));
        return false;
    }
    if (!record.ended.isValid())
        record.ended = nowUtc();
    if (!database_.begin(error))
        return false;
    auto fail = [&] {
        database_.rollback();
        return false;
    };
    // Only a running unit is finished: a recorded verdict or an interruption is never replaced.
    QSqlQuery check(database_.db());
    check.prepare(QStringLiteral("SELECT status, %1 FROM units WHERE unit_id = ?")
                      .arg(hasLeases() ? QStringLiteral("lease_id") : QStringLiteral("NULL")));
    bind(check, {record.id});
    if (!ResultDatabase::run(check, error))
        return fail();
    QString found;
    QString lease;
    if (check.next()) {
        found = check.value(0).toString();
        lease = check.value(1).toString();
    }
    check.finish();
    const bool ours = found == QLatin1String("interrupted") && !lease.isEmpty() && lease == lease_;
    if (found != QLatin1String("running") && !ours) {
        if (error)
            *error = found.isEmpty()
                         ? tr("unit %1 (serial %2) was never begun in the results database")
                               .arg(record.id, record.serial)
                         : tr("unit %1 (serial %2) is already recorded as %3; its record is kept")
                               .arg(record.id, record.serial, found);
        return fail();
    }
    if (!writeChildren(record, error))
        return fail();
    if (hook_)
        hook_();
    QSqlQuery q(database_.db());
    q.prepare(QStringLiteral(
        "UPDATE units SET ended_utc = ?, status = ?, failure_reason = ?, operator_name = ?"
        " WHERE unit_id = ? AND status IN ('running', 'interrupted')"));
    // A database from before station errors has no 'error' status: it keeps them as aborted,
    // which is kept out of yield there too.
    const UnitStatus status =
        record.status == UnitStatus::Error && !hasAttempts() ? UnitStatus::Aborted : record.status;
    bind(q, {UnitRecordJson::timeText(record.ended), unitStatusName(status), record.failureReason,
             record.operatorName, record.id});
    if (!ResultDatabase::run(q, error))
        return fail();
    if (q.numRowsAffected() != 1) {
        if (error)
            *error = tr("unit %1 (serial %2) is not running in the results database: it was "
                        "never begun, or was already finished or marked interrupted")
                         .arg(record.id, record.serial);
        return fail();
    }
    if (!database_.commit(error))
        return fail();
    return true;
}

int ResultStore::markInterrupted(const QString& station, const QDateTime& before, QString* error)
{
    if (!database_.begin(error))
        return -1;
    QSqlQuery q(database_.db());
    q.prepare(QStringLiteral("UPDATE units SET status = 'interrupted', failure_reason = ?"
                             " WHERE station = ? AND status = 'running' AND started_utc < ?%1")
                  .arg(hasLeases() ? QStringLiteral(" AND lease_id IS NULL") : QString()));
    bind(q, {interruptedReason(), station, UnitRecordJson::timeText(before)});
    if (!ResultDatabase::run(q, error)) {
        database_.rollback();
        return -1;
    }
    const int count = q.numRowsAffected();
    if (!database_.commit(error)) {
        database_.rollback();
        return -1;
    }
    return count;
}

void ResultStore::identify(UnitRecord& record)
{
    if (record.id.isEmpty())
        record.id = QUuid::createUuid().toString(QUuid::WithoutBraces);
    if (!record.started.isValid())
        record.started = uniqueStartUtc();
}

bool ResultStore::hasLeases() const
{
    return database_.schemaVersion() >= 3;
}

bool ResultStore::hasAttempts() const
{
    return database_.schemaVersion() >= 5;
}

QString ResultStore::statusOf(const QString& unitId, QString* error)
{
    QSqlQuery q(database_.db());
    q.prepare(QStringLiteral("SELECT status FROM units WHERE unit_id = ?"));
    q.addBindValue(unitId);
    if (!ResultDatabase::run(q, error))
        return QString();
    return q.next() ? q.value(0).toString() : QString();
}

} // namespace opentop
