#pragma once

#include "model/eol/Recipe.h"
#include "model/eol/RecipeChecker.h"

#include <QCommandLineOption>
#include <QCoreApplication>
#include <QJsonArray>
#include <memory>
#include <optional>

namespace opentop {

class CliContext;
class Profile;
class ResultDatabase;

// What the eol subcommands share: loading a recipe file with its refusal said once (a
// hand-edited file told how to re-sign it), the checker's problems, the results database
// named by --db (or its default), a recipe's numbers in words.
class EolSupport
{
    Q_DECLARE_TR_FUNCTIONS(opentop::EolSupport)
public:
    struct LoadedRecipe
    {
        Recipe recipe;
        QString checksum;     // the checksum of the recipe as read (computed when unsigned)
        bool signedOk = true; // false: the file's checksum is missing or does not match
    };

    // Loads `path`. Prints why it is refused and sets *exitCode (2 for a file that cannot be
    // read, 3 for one refused). With `allowUnsigned`, a recipe whose only fault is its checksum
    // is returned with signedOk false and nothing is printed (check and sign decide).
    static std::optional<LoadedRecipe> loadRecipe(CliContext& context, const QString& path,
                                                  bool allowUnsigned, int* exitCode);
    // The one recipe file a `recipe` subcommand names (`usage`: its synopsis), loaded as
    // loadRecipe() does; a wrong number of arguments is a usage error (*exitCode 2).
    static std::optional<LoadedRecipe> recipeArgument(CliContext& context, const QStringList& args,
                                                      const QString& usage, bool allowUnsigned,
                                                      int* exitCode);
    // The refusal of a recipe changed by hand, with how to re-sign it.
    static QString unsignedText(const QString& path);

    static QJsonArray problemsJson(const QVector<RecipeProblem>& problems);
    static void printProblems(CliContext& context, const QVector<RecipeProblem>& problems);

    // "1 position, 5 settings, 1 per-unit value, 8 steps"
    static QString countsText(const Recipe& recipe);
    static int settingCount(const Recipe& recipe);
    static int stepCount(const Recipe& recipe);

    // The results database: --db URL, else OPENTOP_EOL_DB, else defaultDatabase(). Prints
    // why it cannot be opened (the URL without its password) and sets *exitCode (2 for a
    // wrong URL or a SQLite file that does not exist, 1 for one that cannot be opened).
    // `create`: a missing SQLite file is made (the first user of a new station).
    static std::unique_ptr<ResultDatabase> openDatabase(CliContext& context, int* exitCode,
                                                        bool create = false);
    // -o FILE, which several subcommands take.
    static QCommandLineOption outputOption();
    // $XDG_DATA_HOME/opentop/results.db (~/.local/share/opentop/results.db).
    static QString defaultDatabase();

    // A number as the recipe holds it: "1500", "2.5".
    static QString number(double value);
    // "1500 r/min", "2.5 s", "90 %"; the number alone when there is no unit.
    static QString withUnit(const QString& value, const QString& unit);
    // The parameter's label in the profile; its name when the profile does not know it.
    static QString label(const Profile* profile, const QString& parameter);
};

} // namespace opentop
