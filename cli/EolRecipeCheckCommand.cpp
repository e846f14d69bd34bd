#include "cli/EolRecipeCheckCommand.h"

#include "cli/CliContext.h"
#include "cli/EolSupport.h"
#include "cli/ExitCode.h"
#include "cli/FileCommandSupport.h"
#include "model/eol/UnitValuesCsv.h"
#include "model/io/DisplayText.h"
#include "model/profile/ProfileRegistry.h"

#include <QCoreApplication>
#include <QJsonObject>

namespace opentop {

namespace {

QString tr(const char* text, const char* comment = nullptr, int n = -1)
{
    return QCoreApplication::translate("opentop::EolRecipeCheckCommand", text, comment, n);
}

} // namespace

QString EolRecipeCheckCommand::summary() const
{
    return tr("Check a recipe against the drive profiles (and per-unit values of a CSV file)");
}

QList<QCommandLineOption> EolRecipeCheckCommand::options() const
{
    return {{QStringLiteral("units"),
             tr("recipe check: also check every unit's per-unit values in this CSV file."),
             tr("CSV")}};
}

int EolRecipeCheckCommand::run(CliContext& context, const QStringList& args)
{
    int code = ExitOk;
    const std::optional<EolSupport::LoadedRecipe> loaded =
        EolSupport::recipeArgument(context, args, synopsis(), true, &code);
    if (!loaded)
        return code;
    const QString path = args.first();
    const Recipe& recipe = loaded->recipe;
    const ProfileRegistry& registry = ProfileRegistry::builtIn();
    QVector<RecipeProblem> problems = RecipeChecker(registry).check(recipe);

    const QString unitsPath = context.parser().value(QStringLiteral("units"));
    int unitsChecked = 0;
    if (context.parser().isSet(QStringLiteral("units"))) {
        QString error;
        const std::optional<UnitValuesCsv> csv = UnitValuesCsv::load(unitsPath, &error);
        if (!csv) {
            context.err() << tr("error: %1 refused: %2")
                                 .arg(DisplayText::escaped(unitsPath),
                                      DisplayText::escapedLines(error))
                          << Qt::endl;
            return ExitInvalid;
        }
        // Per-unit values are only checked against a recipe that is itself right.
        if (problems.isEmpty()) {
            for (const QString& serial : csv->serials()) {
                if (!csv->valuesFor(recipe, registry, serial, &error))
                    problems << RecipeProblem{tr("%1, serial %2").arg(unitsPath, serial), error};
                ++unitsChecked;
            }
        }
    }

    const bool valid = problems.isEmpty() && loaded->signedOk;
    if (context.json()) {
        QJsonObject o{{QStringLiteral("command"), QStringLiteral("eol recipe check")},
                      {QStringLiteral("file"), path},
                      {QStringLiteral("valid"), valid},
                      {QStringLiteral("signed"), loaded->signedOk},
                      {QStringLiteral("product"), recipe.product},
                      {QStringLiteral("revision"), recipe.revision},
                      {QStringLiteral("checksum"), loaded->checksum},
                      {QStringLiteral("positions"), int(recipe.positions.size())},
                      {QStringLiteral("settings"), EolSupport::settingCount(recipe)},
                      {QStringLiteral("steps"), EolSupport::stepCount(recipe)},
                      {QStringLiteral("problems"), EolSupport::problemsJson(problems)}};
        if (!unitsPath.isEmpty())
            o.insert(QStringLiteral("unitsChecked"), unitsChecked);
        FileCommandSupport::printJson(context, o);
    } else {
        EolSupport::printProblems(context, problems);
    }
    if (!loaded->signedOk)
        context.err() << tr("error: %1").arg(EolSupport::unsignedText(path)) << Qt::endl;
    if (!problems.isEmpty()) {
        context.err() << tr("%1 is not valid: %n problem(s); nothing may be run with it", nullptr,
                            int(problems.size()))
                             .arg(DisplayText::escaped(path))
                      << Qt::endl;
    }
    if (!valid)
        return ExitInvalid;
    if (!context.json()) {
        // The product and revision are the file's text, shown escaped (issue 28).
        context.out() << tr("valid: %1 revision %2: %3")
                             .arg(DisplayText::escaped(recipe.product),
                                  DisplayText::escaped(recipe.revision),
                                  EolSupport::countsText(recipe));
        if (!unitsPath.isEmpty())
            context.out() << tr("; %n unit(s) of %1 checked", nullptr, unitsChecked)
                                 .arg(DisplayText::escaped(unitsPath));
        context.out() << Qt::endl;
    }
    return ExitOk;
}

} // namespace opentop
