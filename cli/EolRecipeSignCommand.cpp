#include "cli/EolRecipeSignCommand.h"

#include "cli/CliContext.h"
#include "cli/EolSupport.h"
#include "cli/ExitCode.h"
#include "cli/FileCommandSupport.h"
#include "model/eol/RecipeFile.h"
#include "model/io/DisplayText.h"
#include "model/profile/ProfileRegistry.h"

#include <QCoreApplication>
#include <QJsonObject>

namespace opentop {

namespace {

QString tr(const char* text, const char* comment = nullptr, int n = -1)
{
    return QCoreApplication::translate("opentop::EolRecipeSignCommand", text, comment, n);
}

} // namespace

QString EolRecipeSignCommand::summary() const
{
    return tr("Accept a recipe edited by hand: a new checksum, only when it passes check");
}

int EolRecipeSignCommand::run(CliContext& context, const QStringList& args)
{
    int code = ExitOk;
    const std::optional<EolSupport::LoadedRecipe> loaded =
        EolSupport::recipeArgument(context, args, synopsis(), true, &code);
    if (!loaded)
        return code;
    const QString path = args.first();
    const QVector<RecipeProblem> problems =
        RecipeChecker(ProfileRegistry::builtIn()).check(loaded->recipe);
    if (!problems.isEmpty()) {
        if (context.json())
            FileCommandSupport::printJson(
                context, {{QStringLiteral("command"), QStringLiteral("eol recipe sign")},
                          {QStringLiteral("file"), path},
                          {QStringLiteral("signed"), false},
                          {QStringLiteral("problems"), EolSupport::problemsJson(problems)}});
        else
            EolSupport::printProblems(context, problems);
        context.err() << tr("error: %1 does not pass check (%n problem(s)); not signed", nullptr,
                            int(problems.size()))
                             .arg(DisplayText::escaped(path))
                      << Qt::endl;
        return ExitInvalid;
    }
    QString error;
    if (!loaded->signedOk && !RecipeFile::save(loaded->recipe, path, &error)) {
        context.err() << tr("error: %1; not signed").arg(DisplayText::escapedLines(error))
                      << Qt::endl;
        return ExitUsage;
    }
    const QString checksum = RecipeFile::checksumOf(loaded->recipe);
    if (context.json())
        FileCommandSupport::printJson(
            context, {{QStringLiteral("command"), QStringLiteral("eol recipe sign")},
                      {QStringLiteral("file"), path},
                      {QStringLiteral("signed"), true},
                      {QStringLiteral("changed"), !loaded->signedOk},
                      {QStringLiteral("checksum"), checksum}});
    else if (loaded->signedOk)
        context.out() << tr("%1 is signed already (%2); nothing changed")
                             .arg(DisplayText::escaped(path), checksum)
                      << Qt::endl;
    else
        context.out() << tr("signed %1: %2 revision %3, %4")
                             .arg(DisplayText::escaped(path),
                                  DisplayText::escaped(loaded->recipe.product),
                                  DisplayText::escaped(loaded->recipe.revision), checksum)
                      << Qt::endl;
    return ExitOk;
}

} // namespace opentop
