#pragma once

#include "cli/EolSubcommand.h"
#include "model/eol/Recipe.h"

namespace opentop {

class Profile;

// `eol recipe show RECIPE [--json]`: a recipe for people: its positions (machine number,
// family, variants, firmware), each position's settings by their labels with value and unit,
// per-unit values with their ranges, and the test steps in words with their limits.
class EolRecipeShowCommand : public EolSubcommand
{
public:
    QString name() const override { return QStringLiteral("recipe show"); }
    QString synopsis() const override { return QStringLiteral("recipe show RECIPE [--json]"); }
    QString summary() const override;
    int run(CliContext& context, const QStringList& args) override;

    // "'Current speed' mean: 1450 … 1550 r/min"
    static QString limitText(const Profile* profile, const RecipeLimit& limit);

private:
    static void printPosition(CliContext& context, const Recipe& recipe, int index);
};

} // namespace opentop
