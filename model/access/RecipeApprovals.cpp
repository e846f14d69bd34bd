#include "model/access/RecipeApprovals.h"

#include "model/eol/ResultDatabase.h"
#include "model/eol/UnitRecordJson.h"

#include <QSqlError>
#include <QSqlQuery>
#include <QUuid>

namespace opentop {

RecipeApprovals::RecipeApprovals(ResultDatabase& database)
    : database_(database)
{
}

QString RecipeApprovals::draftText(const QString& recipeName, const QString& revision)
{
    return tr("recipe \"%1\" rev. %2 is a draft: this version (its checksum) is not approved, so "
              "it does not run. An engineer approves it (Approve… in the recipe editor, or "
              "opentop-cli eol recipe approve FILE --user NAME).")
        .arg(recipeName, revision);
}

std::optional<RecipeApproval> RecipeApprovals::current(const QString& checksum, QString* error)
{
    if (error)
        error->clear();
    QSqlQuery q(database_.db());
    q.prepare(QStringLiteral(
        "SELECT approval_id, recipe_checksum, recipe_name, recipe_revision, approver,"
        " approved_utc, station FROM recipe_approvals WHERE recipe_checksum = ? AND superseded = 0"
        " ORDER BY approved_utc DESC"));
    q.addBindValue(checksum);
    if (!ResultDatabase::run(q, error) || !q.next())
        return std::nullopt;
    RecipeApproval a;
    a.id = q.value(0).toString();
    a.checksum = q.value(1).toString();
    a.recipeName = q.value(2).toString();
    a.revision = q.value(3).toString();
    a.approver = q.value(4).toString();
    a.approved = UnitRecordJson::timeFromText(q.value(5).toString());
    a.station = q.value(6).toString();
    return a;
}

std::optional<RecipeApproval> RecipeApprovals::approve(const QString& recipeName,
                                                       const QString& revision,
                                                       const QString& checksum,
                                                       const QString& approver,
                                                       const QString& station, QString* error)
{
    if (checksum.isEmpty()) {
        if (error)
            *error = tr("a recipe without a checksum cannot be approved: sign it first");
        return std::nullopt;
    }
    if (!database_.begin(error))
        return std::nullopt;
    auto fail = [&] {
        database_.rollback();
        return std::nullopt;
    };
    if (auto existing = current(checksum, error)) {
        database_.rollback();
        return existing;
    }
    if (error && !error->isEmpty())
        return fail();
    QSqlQuery q(database_.db());
    q.prepare(QStringLiteral("UPDATE recipe_approvals SET superseded = 1"
                             " WHERE recipe_name = ? AND recipe_checksum <> ? AND superseded = 0"));
    q.addBindValue(recipeName);
    q.addBindValue(checksum);
    if (!ResultDatabase::run(q, error))
        return fail();
    RecipeApproval a;
    a.id = QUuid::createUuid().toString(QUuid::WithoutBraces);
    a.checksum = checksum;
    a.recipeName = recipeName;
    a.revision = revision;
    a.approver = approver;
    a.approved =
        UnitRecordJson::timeFromText(UnitRecordJson::timeText(QDateTime::currentDateTimeUtc()));
    a.station = station;
    q.prepare(
        QStringLiteral("INSERT INTO recipe_approvals (approval_id, recipe_checksum, recipe_name,"
                       " recipe_revision, approver, approved_utc, station, superseded)"
                       " VALUES (?, ?, ?, ?, ?, ?, ?, 0)"));
    for (const QString& v : {a.id, a.checksum, a.recipeName, a.revision, a.approver,
                             UnitRecordJson::timeText(a.approved), a.station})
        q.addBindValue(v.isNull() ? QString(QLatin1String("")) : v);
    if (!ResultDatabase::run(q, error) || !database_.commit(error))
        return fail();
    return a;
}

} // namespace opentop
