// Users, roles, recipe approvals and the audit trail (issue 25, item 5) on a real SQLite file and
// on a real PostgreSQL server the test starts (PostgresServer): the same rules on both.
#include "model/access/AccessCheck.h"
#include "model/access/AuditTrail.h"
#include "model/access/PasswordHash.h"
#include "model/access/RecipeApprovals.h"
#include "model/eol/ResultDatabase.h"
#include "model/eol/ResultQueries.h"
#include "model/eol/ResultSchema.h"
#include "model/eol/ResultStore.h"
#include "tests/support/EolSampleUnit.h"
#include "tests/support/PostgresServer.h"

#include <QSqlQuery>
#include <QTemporaryDir>
#include <QThread>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

QVector<AuditEntry> auditOf(ResultDatabase& db)
{
    QString error;
    const auto entries = AuditTrail(db).query(AuditFilter(), &error);
    EXPECT_TRUE(entries) << error.toStdString();
    return entries.value_or(QVector<AuditEntry>());
}

bool hasAudit(ResultDatabase& db, const QString& user, const QString& action,
              const QString& detailPart = QString())
{
    for (const AuditEntry& e : auditOf(db))
        if (e.user == user && e.action == action && e.detail.contains(detailPart) &&
            e.station == QLatin1String("line-1/st-3") && e.time.isValid())
            return true;
    return false;
}

// The whole story on one database: unmanaged, the first administrator, roles, refusals,
// approvals and a unit record naming its approval.
void exercise(const QString& url)
{
    QString error;
    auto db = ResultDatabase::open(url, &error);
    ASSERT_TRUE(db) << error.toStdString();
    EXPECT_EQ(db->schemaVersion(), 6);
    AccessCheck access(*db, QStringLiteral("line-1/st-3"));

    // No users: an unmanaged station allows everything, as before.
    EXPECT_EQ(access.managed(&error), 0);
    const AccessDecision open = access.authorize(Privilege::LeaveProduction, Identity{}, QString());
    EXPECT_TRUE(open.allowed);
    EXPECT_FALSE(open.managed);

    // The first user must be an administrator and needs no identity.
    StationUser first;
    first.name = QStringLiteral("olga");
    first.role = Role::Operator;
    bool refused = false;
    EXPECT_FALSE(access.addUser(Identity{}, first, QStringLiteral("secret-1"), &error, &refused));
    EXPECT_TRUE(refused);
    EXPECT_TRUE(error.contains(QStringLiteral("administrator"))) << error.toStdString();
    StationUser admin;
    admin.name = QStringLiteral("ada");
    admin.displayName = QStringLiteral("Ada Admin");
    admin.role = Role::Administrator;
    ASSERT_TRUE(access.addUser(Identity{}, admin, QStringLiteral("adm-pass"), &error))
        << error.toStdString();
    EXPECT_EQ(access.managed(&error), 1);

    // Now an identity is needed: nobody, and a wrong password, add nobody.
    EXPECT_FALSE(access.addUser(Identity{}, first, QStringLiteral("secret-1"), &error, &refused));
    EXPECT_TRUE(refused);
    EXPECT_FALSE(access.addUser(Identity{QStringLiteral("ada"), QStringLiteral("wrong")}, first,
                                QStringLiteral("secret-1"), &error, &refused));
    const Identity ada{QStringLiteral("ada"), QStringLiteral("adm-pass")};
    ASSERT_TRUE(access.addUser(ada, first, QStringLiteral("same-pw"), &error))
        << error.toStdString();
    StationUser eng;
    eng.name = QStringLiteral("erik");
    eng.role = Role::Engineer;
    ASSERT_TRUE(access.addUser(ada, eng, QStringLiteral("same-pw"), &error)) << error.toStdString();
    StationUser tech;
    tech.name = QStringLiteral("tom");
    tech.role = Role::Technician;
    ASSERT_TRUE(access.addUser(ada, tech, QStringLiteral("tech-pw"), &error));
    EXPECT_FALSE(access.addUser(ada, tech, QStringLiteral("tech-pw"), &error, &refused))
        << "a name is taken once";

    // Stored as salted slow hashes: never the password, different for the same password.
    QSqlQuery q(db->db());
    ASSERT_TRUE(q.exec(QStringLiteral(
        "SELECT user_name, password_hash, salt, iterations FROM users ORDER BY user_name")));
    QHash<QString, QString> hashes;
    while (q.next()) {
        EXPECT_FALSE(q.value(1).toString().contains(QStringLiteral("same-pw")));
        EXPECT_FALSE(q.value(1).toString().contains(QStringLiteral("adm-pass")));
        EXPECT_GE(q.value(3).toInt(), 100000);
        hashes.insert(q.value(0).toString(), q.value(1).toString() + q.value(2).toString());
    }
    q.finish();
    ASSERT_EQ(hashes.size(), 4);
    EXPECT_NE(hashes.value(QStringLiteral("olga")), hashes.value(QStringLiteral("erik")))
        << "the same password hashes differently for each user (salt)";

    // The one table: an operator runs units and resets alarms, nothing else.
    const Identity olga{QStringLiteral("olga"), QStringLiteral("same-pw")};
    EXPECT_TRUE(access.login(olga).allowed);
    EXPECT_TRUE(hasAudit(*db, QStringLiteral("olga"), QStringLiteral("login")));
    EXPECT_TRUE(access.authorize(Privilege::ResetAlarm, olga, QString()).allowed);
    for (Privilege p : {Privilege::LeaveProduction, Privilege::EditRecipe, Privilege::ApproveRecipe,
                        Privilege::OverrideRetestLimit, Privilege::ManageUsers}) {
        const AccessDecision d = access.authorize(p, olga, QStringLiteral("test"));
        EXPECT_FALSE(d.allowed) << AccessPolicy::privilegeKey(p).toStdString();
        EXPECT_TRUE(d.message.contains(QStringLiteral("olga (operator) may not")))
            << d.message.toStdString();
    }
    EXPECT_TRUE(hasAudit(*db, QStringLiteral("olga"), QStringLiteral("refused"),
                         QStringLiteral("leave-production")));
    const Identity tom{QStringLiteral("tom"), QStringLiteral("tech-pw")};
    EXPECT_TRUE(access.authorize(Privilege::OverrideRetestLimit, tom, QString()).allowed);
    EXPECT_FALSE(access.authorize(Privilege::LeaveProduction, tom, QString()).allowed);
    const Identity erik{QStringLiteral("erik"), QStringLiteral("same-pw")};
    EXPECT_TRUE(access.authorize(Privilege::LeaveProduction, erik, QString()).allowed);
    EXPECT_TRUE(hasAudit(*db, QStringLiteral("erik"), QStringLiteral("privilege"),
                         QStringLiteral("leave-production")));
    EXPECT_FALSE(access.authorize(Privilege::ManageUsers, erik, QString()).allowed);

    // A wrong password is refused without saying whether the name exists, and audited.
    const AccessDecision wrong =
        access.login(Identity{QStringLiteral("olga"), QStringLiteral("x")});
    EXPECT_FALSE(wrong.allowed);
    EXPECT_EQ(wrong.message, QStringLiteral("wrong user name or password"));
    EXPECT_EQ(access.login(Identity{QStringLiteral("nobody"), QStringLiteral("x")}).message,
              wrong.message);
    EXPECT_TRUE(hasAudit(*db, QString(), QStringLiteral("login-failed"), QStringLiteral("olga")));

    // Approvals: an operator cannot approve; an engineer can; another checksum of the same
    // recipe supersedes it.
    std::optional<RecipeApproval> approval;
    EXPECT_FALSE(access
                     .approveRecipe(olga, QStringLiteral("C-200"), QStringLiteral("A"),
                                    QStringLiteral("sha256:aaa"), &approval)
                     .allowed);
    EXPECT_FALSE(approval);
    RecipeApprovals approvals(*db);
    EXPECT_FALSE(approvals.current(QStringLiteral("sha256:aaa"), &error));
    EXPECT_TRUE(error.isEmpty()) << error.toStdString();
    ASSERT_TRUE(access
                    .approveRecipe(erik, QStringLiteral("C-200"), QStringLiteral("A"),
                                   QStringLiteral("sha256:aaa"), &approval)
                    .allowed);
    ASSERT_TRUE(approval);
    EXPECT_EQ(approval->approver, QStringLiteral("erik"));
    EXPECT_TRUE(hasAudit(*db, QStringLiteral("erik"), QStringLiteral("recipe-approved"),
                         QStringLiteral("sha256:aaa")));
    const auto found = approvals.current(QStringLiteral("sha256:aaa"), &error);
    ASSERT_TRUE(found);
    EXPECT_EQ(found->id, approval->id);
    EXPECT_EQ(found->station, QStringLiteral("line-1/st-3"));
    std::optional<RecipeApproval> second;
    ASSERT_TRUE(access
                    .approveRecipe(erik, QStringLiteral("C-200"), QStringLiteral("B"),
                                   QStringLiteral("sha256:bbb"), &second)
                    .allowed);
    EXPECT_FALSE(approvals.current(QStringLiteral("sha256:aaa"), &error))
        << "the earlier version is superseded";
    EXPECT_TRUE(approvals.current(QStringLiteral("sha256:bbb"), &error));

    // A unit names its approval and approver, read back as written.
    UnitRecord unit = test::eolSampleUnit(QStringLiteral("SN-ACCESS"));
    unit.approvalId = second->id;
    unit.approver = second->approver;
    unit.operatorName = QStringLiteral("olga");
    ResultStore store(*db);
    ASSERT_TRUE(store.beginUnit(unit, &error)) << error.toStdString();
    ASSERT_TRUE(store.finishUnit(unit, &error)) << error.toStdString();
    const auto loaded = ResultQueries(*db).load(unit.id, &error);
    ASSERT_TRUE(loaded) << error.toStdString();
    EXPECT_EQ(loaded->approvalId, second->id);
    EXPECT_EQ(loaded->approver, QStringLiteral("erik"));

    // A disabled user cannot log in; the last administrator is never disabled.
    EXPECT_FALSE(access.setActive(ada, QStringLiteral("ada"), false, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("last active administrator")));
    ASSERT_TRUE(access.setActive(ada, QStringLiteral("olga"), false, &error))
        << error.toStdString();
    const AccessDecision disabled = access.login(olga);
    EXPECT_FALSE(disabled.allowed);
    EXPECT_TRUE(disabled.message.contains(QStringLiteral("disabled")));
    EXPECT_TRUE(hasAudit(*db, QStringLiteral("ada"), QStringLiteral("user-disabled")));
    // A new password: the old one no longer works.
    ASSERT_TRUE(access.setPassword(tom, QStringLiteral("tom"), QStringLiteral("new-tech"), &error))
        << error.toStdString();
    EXPECT_FALSE(access.login(tom).allowed);
    EXPECT_TRUE(access.login(Identity{QStringLiteral("tom"), QStringLiteral("new-tech")}).allowed);

    // The trail filtered by user.
    AuditFilter byErik;
    byErik.user = QStringLiteral("erik");
    const auto erikOnly = AuditTrail(*db).query(byErik, &error);
    ASSERT_TRUE(erikOnly);
    EXPECT_GE(erikOnly->size(), 3);
    for (const AuditEntry& e : *erikOnly)
        EXPECT_EQ(e.user, QStringLiteral("erik"));
}

} // namespace

TEST(PasswordHashTest, SaltedSlowAndNeverThePassword)
{
    const PasswordHash a = PasswordHash::make(QStringLiteral("line-2024"));
    const PasswordHash b = PasswordHash::make(QStringLiteral("line-2024"));
    EXPECT_GE(a.iterations, PasswordHash::kMinimumIterations);
    EXPECT_NE(a.salt, b.salt);
    EXPECT_NE(a.hash, b.hash) << "the same password, another salt, another hash";
    EXPECT_FALSE(a.hash.contains("line-2024"));
    EXPECT_EQ(QByteArray::fromBase64(a.hash).size(), 32);
    EXPECT_TRUE(a.matches(QStringLiteral("line-2024")));
    EXPECT_FALSE(a.matches(QStringLiteral("line-2025")));
    EXPECT_FALSE(a.matches(QString()));
    EXPECT_FALSE(PasswordHash().matches(QString())) << "no hash matches nothing";
    // RFC 7914 / common test vector for PBKDF2-HMAC-SHA256: "password"/"salt", 1 iteration.
    PasswordHash known;
    known.salt = QByteArray("salt").toBase64();
    known.iterations = 1;
    known.hash =
        QByteArray::fromHex("120fb6cffcf8b32c43e7225256c4f837a86548c92ccc35480805987cb70be17b")
            .toBase64();
    EXPECT_TRUE(known.matches(QStringLiteral("password")));
}

TEST(AccessPolicyTest, OneTableOfPrivileges)
{
    EXPECT_TRUE(AccessPolicy::allows(Role::Operator, Privilege::RunUnits));
    EXPECT_TRUE(AccessPolicy::allows(Role::Operator, Privilege::ResetAlarm));
    EXPECT_FALSE(AccessPolicy::allows(Role::Operator, Privilege::OverrideRetestLimit));
    EXPECT_TRUE(AccessPolicy::allows(Role::Technician, Privilege::OverrideRetestLimit));
    EXPECT_FALSE(AccessPolicy::allows(Role::Technician, Privilege::EditRecipe));
    EXPECT_TRUE(AccessPolicy::allows(Role::Engineer, Privilege::ApproveRecipe));
    EXPECT_TRUE(AccessPolicy::allows(Role::Engineer, Privilege::LeaveProduction));
    EXPECT_FALSE(AccessPolicy::allows(Role::Engineer, Privilege::ManageUsers));
    EXPECT_TRUE(AccessPolicy::allows(Role::Administrator, Privilege::ManageUsers));
    for (const QString& key : AccessPolicy::roleKeys())
        EXPECT_EQ(AccessPolicy::roleKey(*AccessPolicy::roleFromKey(key)), key);
    EXPECT_FALSE(AccessPolicy::roleFromKey(QStringLiteral("root")));
}

TEST(AccessCheckTest, UsersRolesApprovalsAndAuditOnSqlite)
{
    QTemporaryDir dir;
    exercise(dir.filePath(QStringLiteral("results.db")));
}

TEST(AccessCheckTest, UsersRolesApprovalsAndAuditOnPostgres)
{
    if (test::PostgresServer::skipRequested())
        GTEST_SKIP() << "OPENTOP_TEST_PG_SKIP=1: PostgreSQL tests skipped on request";
    QString error;
    test::PostgresServer* server = test::PostgresServer::shared(&error);
    ASSERT_TRUE(server) << "cannot start a PostgreSQL server for the tests: "
                        << error.toStdString();
    const QString url = server->createDatabase(QStringLiteral("eol_access"), &error);
    ASSERT_FALSE(url.isEmpty()) << error.toStdString();
    exercise(url);
}

TEST(AccessCheckTest, ADatabaseAtVersionThreeGainsUsersAndKeepsItsUnits)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("old.db"));
    QString error;
    UnitRecord unit = test::eolSampleUnit(QStringLiteral("SN-ACCESS"));
    {
        auto old = ResultDatabase::open(path, &error, 3);
        ASSERT_TRUE(old) << error.toStdString();
        ResultStore store(*old);
        ASSERT_TRUE(store.beginUnit(unit, &error)) << error.toStdString();
        ASSERT_TRUE(store.finishUnit(unit, &error)) << error.toStdString();
    }
    auto db = ResultDatabase::open(path, &error);
    ASSERT_TRUE(db) << error.toStdString();
    EXPECT_EQ(db->schemaVersion(), ResultSchema::currentVersion());
    const auto loaded = ResultQueries(*db).load(unit.id, &error);
    ASSERT_TRUE(loaded) << error.toStdString();
    EXPECT_TRUE(loaded->approver.isEmpty()) << "a unit from before approvals names none";
    EXPECT_EQ(AccessCheck(*db, QStringLiteral("s")).managed(&error), 0);
}

TEST(AuditTrailTest, ALimitKeepsTheNewestEntriesOldestFirstAndFilters)
{
    QTemporaryDir dir;
    QString error;
    auto db = ResultDatabase::open(dir.filePath(QStringLiteral("r.db")), &error);
    ASSERT_TRUE(db) << error.toStdString();
    AuditTrail trail(*db);
    for (int i = 0; i < 5; ++i) {
        ASSERT_TRUE(trail.record(i % 2 ? QStringLiteral("st-2") : QStringLiteral("st-1"),
                                 QStringLiteral("u%1").arg(i), QStringLiteral("login"),
                                 QString::number(i), &error))
            << error.toStdString();
        QThread::msleep(3); // the database clock orders them
    }
    AuditFilter newest;
    newest.limit = 2;
    auto entries = trail.query(newest, &error);
    ASSERT_TRUE(entries) << error.toStdString();
    ASSERT_EQ(entries->size(), 2);
    EXPECT_EQ(entries->at(0).detail, QStringLiteral("3"));
    EXPECT_EQ(entries->at(1).detail, QStringLiteral("4"));
    EXPECT_LE(entries->at(0).time, entries->at(1).time);
    AuditFilter station;
    station.station = QStringLiteral("st-2");
    entries = trail.query(station, &error);
    ASSERT_TRUE(entries);
    ASSERT_EQ(entries->size(), 2);
    EXPECT_EQ(entries->at(0).user, QStringLiteral("u1"));
    AuditFilter later;
    later.since = QDateTime::currentDateTimeUtc().addSecs(60);
    entries = trail.query(later, &error);
    ASSERT_TRUE(entries);
    EXPECT_TRUE(entries->isEmpty());
}
