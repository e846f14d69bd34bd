#pragma once

#include "cli/EolSubcommand.h"

#include <QJsonArray>
#include <QVector>
#include <optional>

namespace opentop {

class Recipe;

// `eol recipe create (--from-backup FILE | --drives LIST) --product P --revision R -o FILE`:
// a recipe from a golden unit (a backup file, or its drives read off the bus), with the
// family's default test steps, checked and written atomically; an existing file only with
// --force. With --measure --yes the golden drives run the recipe's steps once and the hold
// limits come from what they measured (GoldenMeasure); without --yes it only says what would run.
class EolRecipeCreateCommand : public EolSubcommand
{
public:
    QString name() const override { return QStringLiteral("recipe create"); }
    QString synopsis() const override
    {
        return QStringLiteral("recipe create (--from-backup FILE | --drives LIST) --product NAME "
                              "--revision REV -o RECIPE [--measure [--margin PERCENT] --yes] "
                              "[--force]");
    }
    QString summary() const override;
    QList<QCommandLineOption> options() const override;
    int run(CliContext& context, const QStringList& args) override;

private:
    // The recipe from the golden drives on the bus (RecipeFromDrives: variants proven, settings
    // read); nullopt (with *exitCode) when a drive failed, said on stderr.
    static std::optional<Recipe> readGolden(CliContext& context, const QVector<int>& ids,
                                            const QString& product, const QString& revision,
                                            int* exitCode);
    // Runs the golden unit through `recipe`'s steps and tightens its hold limits around what it
    // measured; false (with *exitCode) when it did not run or did not pass.
    static bool measure(CliContext& context, Recipe* recipe, double margin, int* exitCode,
                        QJsonArray* limits);
};

} // namespace opentop
