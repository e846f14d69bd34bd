#include "cli/EolRecipeApproveCommand.h"

#include "cli/CliContext.h"
#include "cli/CliIdentity.h"
#include "cli/EolSupport.h"
#include "cli/ExitCode.h"
#include "model/access/AccessCheck.h"
#include "model/eol/RecipeChecker.h"
#include "model/eol/ResultDatabase.h"
#include "model/io/DisplayText.h"
#include "model/profile/ProfileRegistry.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QSysInfo>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::EolRecipeApproveCommand", text);
}

} // namespace

QString EolRecipeApproveCommand::synopsis() const
{
    return QStringLiteral("recipe approve RECIPE --user NAME [--db URL]");
}

QString EolRecipeApproveCommand::summary() const
{
    return tr("Approve a signed recipe for the line (an engineer): stations then run it");
}

QList<QCommandLineOption> EolRecipeApproveCommand::options() const
{
    return {{QStringLiteral("db"),
             tr("Results database: an SQLite file or postgresql://user@host/db."), tr("URL")},
            CliIdentity::userOption()};
}

int EolRecipeApproveCommand::run(CliContext& context, const QStringList& args)
{
    QTextStream& err = context.err();
    if (args.size() != 1) {
        err << tr("usage: opentop-cli eol %1").arg(synopsis()) << Qt::endl;
        return ExitUsage;
    }
    int code = ExitOk;
    // Only a signed recipe that passes the checker can be approved: what is approved is what
    // runs.
    const auto loaded = EolSupport::loadRecipe(context, args.first(), false, &code);
    if (!loaded)
        return code;
    const QVector<RecipeProblem> problems =
        RecipeChecker(ProfileRegistry::builtIn()).check(loaded->recipe);
    if (!problems.isEmpty()) {
        err << tr("%1: the recipe is not valid, so it cannot be approved:")
                   .arg(DisplayText::escaped(args.first()))
            << '\n';
        EolSupport::printProblems(context, problems);
        err.flush();
        return ExitInvalid;
    }
    std::unique_ptr<ResultDatabase> db = EolSupport::openDatabase(context, &code);
    if (!db)
        return code;
    const std::optional<Identity> who = CliIdentity::fromOptions(context);
    if (!who)
        return ExitUsage;
    std::optional<RecipeApproval> approval;
    const AccessDecision d =
        AccessCheck(*db, QSysInfo::machineHostName())
            .approveRecipe(*who, loaded->recipe.product, loaded->recipe.revision, loaded->checksum,
                           &approval);
    if (!d.allowed || !approval) {
        err << tr("error: %1; the recipe was not approved")
                   .arg(DisplayText::escapedLines(d.message))
            << Qt::endl;
        return ExitInvalid;
    }
    if (context.json()) {
        context.out() << QJsonDocument(
                             QJsonObject{{QStringLiteral("approval"), approval->id},
                                         {QStringLiteral("recipe"), approval->recipeName},
                                         {QStringLiteral("revision"), approval->revision},
                                         {QStringLiteral("checksum"), approval->checksum},
                                         {QStringLiteral("approver"), approval->approver},
                                         {QStringLiteral("approved"),
                                          approval->approved.toString(Qt::ISODateWithMs)}})
                             .toJson(QJsonDocument::Compact)
                      << '\n';
        return ExitOk;
    }
    context.out() << tr("%1 rev. %2 approved by %3 (approval %4, checksum %5)")
                         .arg(DisplayText::escaped(approval->recipeName),
                              DisplayText::escaped(approval->revision),
                              DisplayText::escaped(approval->approver), approval->id,
                              approval->checksum)
                  << Qt::endl;
    return ExitOk;
}

} // namespace opentop
