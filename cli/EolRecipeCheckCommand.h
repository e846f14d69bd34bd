#pragma once

#include "cli/EolSubcommand.h"

namespace opentop {

// `eol recipe check RECIPE [--units CSV]`: validates a recipe against the profiles
// (RecipeChecker) and, with --units, every unit's per-unit values of a CSV file; prints each
// problem with its path, exit 3 when there is one. A recipe changed by hand is refused until it
// is signed (`eol recipe sign`); its problems are still listed.
class EolRecipeCheckCommand : public EolSubcommand
{
public:
    QString name() const override { return QStringLiteral("recipe check"); }
    QString synopsis() const override
    {
        return QStringLiteral("recipe check RECIPE [--units CSV]");
    }
    QString summary() const override;
    QList<QCommandLineOption> options() const override;
    int run(CliContext& context, const QStringList& args) override;
};

} // namespace opentop
