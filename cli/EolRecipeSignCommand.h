#pragma once

#include "cli/EolSubcommand.h"

namespace opentop {

// `eol recipe sign RECIPE`: accepts a recipe edited by hand by computing its checksum again,
// only when it passes `eol recipe check`; the file is replaced atomically.
class EolRecipeSignCommand : public EolSubcommand
{
public:
    QString name() const override { return QStringLiteral("recipe sign"); }
    QString synopsis() const override { return QStringLiteral("recipe sign RECIPE"); }
    QString summary() const override;
    int run(CliContext& context, const QStringList& args) override;
};

} // namespace opentop
