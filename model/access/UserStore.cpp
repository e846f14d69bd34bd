#include "model/access/UserStore.h"

#include "model/eol/ResultDatabase.h"
#include "model/eol/UnitRecordJson.h"

#include <QRegularExpression>
#include <QSqlError>
#include <QSqlQuery>

namespace opentop {

namespace {

const char* const kColumns =
    "user_name, display_name, role, password_hash, salt, iterations, active, created_utc";

StationUser userFrom(const QSqlQuery& q)
{
    StationUser u;
    u.name = q.value(0).toString();
    u.displayName = q.value(1).toString();
    // A role this program does not know gets the least privilege.
    u.role = AccessPolicy::roleFromKey(q.value(2).toString()).value_or(Role::Operator);
    u.password.hash = q.value(3).toString().toLatin1();
    u.password.salt = q.value(4).toString().toLatin1();
    u.password.iterations = q.value(5).toInt();
    u.active = q.value(6).toInt() != 0;
    u.created = UnitRecordJson::timeFromText(q.value(7).toString());
    return u;
}

} // namespace

UserStore::UserStore(ResultDatabase& database)
    : database_(database)
{
}

QString UserStore::nameProblem(const QString& name)
{
    static const QRegularExpression allowed(QStringLiteral("^[A-Za-z0-9._@-]{1,64}$"));
    if (!allowed.match(name).hasMatch())
        return tr("a user name is 1 to 64 letters, digits or . _ @ - (no spaces): \"%1\"")
            .arg(name);
    return QString();
}

int UserStore::count(QString* error)
{
    QSqlQuery q(database_.db());
    q.prepare(QStringLiteral("SELECT COUNT(*) FROM users"));
    if (!ResultDatabase::run(q, error) || !q.next())
        return -1;
    return q.value(0).toInt();
}

int UserStore::activeAdministrators(QString* error)
{
    QSqlQuery q(database_.db());
    q.prepare(QStringLiteral("SELECT COUNT(*) FROM users WHERE role = ? AND active = 1"));
    q.addBindValue(AccessPolicy::roleKey(Role::Administrator));
    if (!ResultDatabase::run(q, error) || !q.next())
        return -1;
    return q.value(0).toInt();
}

std::optional<StationUser> UserStore::find(const QString& name, QString* error)
{
    QSqlQuery q(database_.db());
    q.prepare(
        QStringLiteral("SELECT %1 FROM users WHERE user_name = ?").arg(QLatin1String(kColumns)));
    q.addBindValue(name);
    if (!ResultDatabase::run(q, error))
        return std::nullopt;
    if (!q.next()) {
        if (error)
            error->clear();
        return std::nullopt;
    }
    return userFrom(q);
}

std::optional<QVector<StationUser>> UserStore::list(QString* error)
{
    QSqlQuery q(database_.db());
    q.prepare(
        QStringLiteral("SELECT %1 FROM users ORDER BY user_name").arg(QLatin1String(kColumns)));
    if (!ResultDatabase::run(q, error))
        return std::nullopt;
    QVector<StationUser> users;
    while (q.next())
        users << userFrom(q);
    return users;
}

bool UserStore::add(const StationUser& u, QString* error)
{
    QSqlQuery q(database_.db());
    q.prepare(QStringLiteral("INSERT INTO users (%1) VALUES (?, ?, ?, ?, ?, ?, ?, ?)")
                  .arg(QLatin1String(kColumns)));
    q.addBindValue(u.name);
    q.addBindValue(u.displayName.isEmpty() ? u.name : u.displayName);
    q.addBindValue(AccessPolicy::roleKey(u.role));
    q.addBindValue(QString::fromLatin1(u.password.hash));
    q.addBindValue(QString::fromLatin1(u.password.salt));
    q.addBindValue(u.password.iterations);
    q.addBindValue(u.active ? 1 : 0);
    q.addBindValue(UnitRecordJson::timeText(u.created.isValid() ? u.created
                                                                : QDateTime::currentDateTimeUtc()));
    return ResultDatabase::run(q, error);
}

bool UserStore::setActive(const QString& name, bool active, QString* error)
{
    QSqlQuery q(database_.db());
    q.prepare(QStringLiteral("UPDATE users SET active = ? WHERE user_name = ?"));
    q.addBindValue(active ? 1 : 0);
    q.addBindValue(name);
    return ResultDatabase::run(q, error);
}

bool UserStore::setPassword(const QString& name, const PasswordHash& p, QString* error)
{
    QSqlQuery q(database_.db());
    q.prepare(QStringLiteral(
        "UPDATE users SET password_hash = ?, salt = ?, iterations = ? WHERE user_name = ?"));
    q.addBindValue(QString::fromLatin1(p.hash));
    q.addBindValue(QString::fromLatin1(p.salt));
    q.addBindValue(p.iterations);
    q.addBindValue(name);
    return ResultDatabase::run(q, error);
}

} // namespace opentop
