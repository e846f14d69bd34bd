// Users, approvals and the audit trail through the real opentop-cli (issue 25, item 5): the
// first administrator, users added with an identity, `eol run` refused without a user, with a
// wrong password and with an unapproved or edited recipe (nothing sent, nothing recorded), and
// run once an engineer approved it, the record naming its approval and approver; `eol audit`.
#include "model/eol/RecipeFile.h"
#include "model/eol/ResultDatabase.h"
#include "model/eol/ResultQueries.h"
#include "tests/e2e/CliProcess.h"
#include "tests/e2e/SimProcess.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcessEnvironment>
#include <QTemporaryDir>

using namespace opentop;
using namespace opentop::test;

namespace {

constexpr int kCurrentSpeed = 0x0109; // DBU status.current_speed (fc 04)

class EolAccessE2e : public ::testing::Test
{
protected:
    void SetUp() override
    {
        QString error;
        ASSERT_TRUE(sim.start({QStringLiteral("--devices"), QStringLiteral("dbu200@1")}, &error))
            << error.toStdString();
        db = dir.filePath(QStringLiteral("results.db"));
        recipe = writeRecipe(1);
    }

    QString writeRecipe(double holdS)
    {
        QString error;
        std::optional<Recipe> r = RecipeFile::load(
            QStringLiteral(OPENTOP_SOURCE_DIR "/docs/examples/recipe-dbu200.json"), &error);
        EXPECT_TRUE(r) << error.toStdString();
        for (RecipeStep& step : r->positions[0].steps)
            if (step.type == RecipeStep::Type::Hold)
                step.duration = holdS;
        const QString path = dir.filePath(QStringLiteral("recipe.json"));
        EXPECT_TRUE(RecipeFile::save(*r, path, &error)) << error.toStdString();
        return path;
    }

    // opentop-cli ARGS with OPENTOP_PASSWORD / OPENTOP_NEW_PASSWORD set when given.
    CliResult cli(const QStringList& args, const QString& password = QString(),
                  const QString& newPassword = QString())
    {
        QProcess process;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove(QStringLiteral("OPENTOP_PASSWORD"));
        env.remove(QStringLiteral("OPENTOP_NEW_PASSWORD"));
        if (!password.isNull())
            env.insert(QStringLiteral("OPENTOP_PASSWORD"), password);
        if (!newPassword.isNull())
            env.insert(QStringLiteral("OPENTOP_NEW_PASSWORD"), newPassword);
        process.setProcessEnvironment(env);
        // No terminal: a missing password is an error, never a prompt that waits.
        process.setStandardInputFile(QProcess::nullDevice());
        process.start(cliProgram(), args);
        if (!process.waitForStarted(5000))
            return CliResult{-1, QString(), QStringLiteral("<cannot start opentop-cli>")};
        return finishCli(process, 60000);
    }

    CliResult run(const QString& serial, const QStringList& extra,
                  const QString& password = QString())
    {
        return cli(QStringList{QStringLiteral("--port"), sim.pty, QStringLiteral("eol"),
                               QStringLiteral("run"), recipe, QStringLiteral("--serial"), serial,
                               QStringLiteral("--db"), db, QStringLiteral("--station"),
                               QStringLiteral("e2e"), QStringLiteral("--value"),
                               QStringLiteral("1:spno3.speed=1500")} +
                       extra,
                   password);
    }

    QStringList eol(const QStringList& args) const
    {
        return QStringList{QStringLiteral("eol")} + args + QStringList{QStringLiteral("--db"), db};
    }

    int recordsOf(const QString& serial)
    {
        QString error;
        auto database = ResultDatabase::open(db, &error);
        EXPECT_TRUE(database) << error.toStdString();
        const auto history = ResultQueries(*database).history(serial, &error);
        return history ? int(history->size()) : -1;
    }

    SimProcess sim;
    QTemporaryDir dir;
    QString db;
    QString recipe;
};

QString both(const CliResult& r)
{
    return r.out + r.err;
}

} // namespace

TEST_F(EolAccessE2e, OnlyAnApprovedRecipeRunsAndOnlyForAUserTheRecordNamesTheApprover)
{
    // Unmanaged: a run works as before users existed.
    CliResult r = run(QStringLiteral("SN-0"), {});
    ASSERT_EQ(r.code, 0) << both(r).toStdString();

    // The first user must be an administrator; it needs no identity.
    r = cli(eol({QStringLiteral("user"), QStringLiteral("add"), QStringLiteral("ada"),
                 QStringLiteral("--role"), QStringLiteral("operator")}),
            QString(), QStringLiteral("adm-pass"));
    EXPECT_EQ(r.code, 3) << both(r).toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("first user must be an administrator")));
    r = cli(eol({QStringLiteral("user"), QStringLiteral("add"), QStringLiteral("ada"),
                 QStringLiteral("--role"), QStringLiteral("administrator")}),
            QString(), QStringLiteral("adm-pass"));
    ASSERT_EQ(r.code, 0) << both(r).toStdString();
    // Then only with an administrator's identity.
    r = cli(eol({QStringLiteral("user"), QStringLiteral("add"), QStringLiteral("olga"),
                 QStringLiteral("--role"), QStringLiteral("operator")}),
            QString(), QStringLiteral("op-pass"));
    EXPECT_EQ(r.code, 2) << both(r).toStdString();
    for (const auto& [name, role, pw] :
         {std::tuple{"olga", "operator", "op-pass"}, std::tuple{"erik", "engineer", "eng-pass"}}) {
        r = cli(eol({QStringLiteral("user"), QStringLiteral("add"), QString::fromLatin1(name),
                     QStringLiteral("--role"), QString::fromLatin1(role), QStringLiteral("--user"),
                     QStringLiteral("ada")}),
                QStringLiteral("adm-pass"), QString::fromLatin1(pw));
        ASSERT_EQ(r.code, 0) << both(r).toStdString();
    }
    r = cli(eol({QStringLiteral("user"), QStringLiteral("list")}));
    ASSERT_EQ(r.code, 0);
    EXPECT_TRUE(r.out.contains(QStringLiteral("olga")) &&
                r.out.contains(QStringLiteral("engineer")));
    EXPECT_FALSE(r.out.contains(QStringLiteral("op-pass")));

    // Managed now: no user, a wrong password, an unapproved recipe: refused, nothing sent.
    r = run(QStringLiteral("SN-1"), {});
    EXPECT_EQ(r.code, 2) << both(r).toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("--user"))) << r.err.toStdString();
    r = run(QStringLiteral("SN-1"), {QStringLiteral("--user"), QStringLiteral("olga")},
            QStringLiteral("not-it"));
    EXPECT_EQ(r.code, 3) << both(r).toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("wrong user name or password")));
    r = run(QStringLiteral("SN-1"), {QStringLiteral("--user"), QStringLiteral("olga")},
            QStringLiteral("op-pass"));
    EXPECT_EQ(r.code, 3) << both(r).toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("is a draft"))) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("An engineer approves it")));
    EXPECT_EQ(recordsOf(QStringLiteral("SN-1")), 0) << "nothing recorded, nothing started";
    EXPECT_EQ(sim.get(1, kCurrentSpeed, 4), 0);

    // An operator cannot approve; an engineer can.
    r = cli(eol({QStringLiteral("recipe"), QStringLiteral("approve"), recipe,
                 QStringLiteral("--user"), QStringLiteral("olga")}),
            QStringLiteral("op-pass"));
    EXPECT_EQ(r.code, 3) << both(r).toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("olga (operator) may not approve a recipe")))
        << r.err.toStdString();
    r = cli(eol({QStringLiteral("recipe"), QStringLiteral("approve"), recipe,
                 QStringLiteral("--user"), QStringLiteral("erik"), QStringLiteral("--json")}),
            QStringLiteral("eng-pass"));
    ASSERT_EQ(r.code, 0) << both(r).toStdString();
    const QString approvalId = QJsonDocument::fromJson(r.out.toUtf8())
                                   .object()
                                   .value(QStringLiteral("approval"))
                                   .toString();
    ASSERT_FALSE(approvalId.isEmpty()) << r.out.toStdString();

    // Approved: the operator's unit runs; its record names the operator, approval and approver.
    r = run(QStringLiteral("SN-1"),
            {QStringLiteral("--user"), QStringLiteral("olga"), QStringLiteral("--json")},
            QStringLiteral("op-pass"));
    ASSERT_EQ(r.code, 0) << both(r).toStdString();
    {
        QString error;
        auto database = ResultDatabase::open(db, &error);
        ASSERT_TRUE(database) << error.toStdString();
        const auto history = ResultQueries(*database).history(QStringLiteral("SN-1"), &error);
        ASSERT_TRUE(history && history->size() == 1) << error.toStdString();
        EXPECT_EQ(history->first().status, UnitStatus::Pass);
        EXPECT_EQ(history->first().operatorName, QStringLiteral("olga"));
        EXPECT_EQ(history->first().approver, QStringLiteral("erik"));
        EXPECT_EQ(history->first().approvalId, approvalId);
    }
    r = cli(eol({QStringLiteral("results"), QStringLiteral("--serial"), QStringLiteral("SN-1")}));
    EXPECT_TRUE(r.out.contains(QStringLiteral("erik"))) << r.out.toStdString();
    // On a managed station the operator is who logs in, not free text.
    r = run(QStringLiteral("SN-2"),
            {QStringLiteral("--user"), QStringLiteral("olga"), QStringLiteral("--operator"),
             QStringLiteral("someone")},
            QStringLiteral("op-pass"));
    EXPECT_EQ(r.code, 2) << both(r).toStdString();

    // An edited recipe (re-signed: another checksum) is a draft again and does not run.
    recipe = writeRecipe(2);
    r = run(QStringLiteral("SN-3"), {QStringLiteral("--user"), QStringLiteral("olga")},
            QStringLiteral("op-pass"));
    EXPECT_EQ(r.code, 3) << both(r).toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("is a draft")));
    EXPECT_EQ(recordsOf(QStringLiteral("SN-3")), 0);

    // The audit trail has the logins, the failed one, the refusals and the approval.
    r = cli(eol({QStringLiteral("audit"), QStringLiteral("--json")}));
    ASSERT_EQ(r.code, 0) << both(r).toStdString();
    QStringList seen;
    for (const QJsonValue& v : QJsonDocument::fromJson(r.out.toUtf8()).array()) {
        const QJsonObject o = v.toObject();
        seen << o.value(QStringLiteral("user")).toString() + QLatin1Char(':') +
                    o.value(QStringLiteral("action")).toString();
    }
    for (const char* expected :
         {"ada:user-added", "olga:login", ":login-failed", "olga:refused", "erik:recipe-approved"})
        EXPECT_TRUE(seen.contains(QString::fromLatin1(expected)))
            << expected << " in " << seen.join(QLatin1Char(' ')).toStdString();
    r = cli(eol({QStringLiteral("audit"), QStringLiteral("--user"), QStringLiteral("erik")}));
    EXPECT_EQ(r.code, 0);
    EXPECT_TRUE(r.out.contains(QStringLiteral("recipe-approved")));
    EXPECT_FALSE(r.out.contains(QStringLiteral("olga")));
    EXPECT_FALSE(r.out.contains(QStringLiteral("op-pass"))) << "never a password";
}
