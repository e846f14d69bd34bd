#pragma once

#include "cli/EolSubcommand.h"

namespace opentop {

// `eol recipe approve RECIPE --user NAME`: records in the results database that this recipe's
// checksum may run on the line (an engineer or above; access/AccessCheck decides).
class EolRecipeApproveCommand : public EolSubcommand
{
public:
    QString name() const override { return QStringLiteral("recipe approve"); }
    QString synopsis() const override;
    QString summary() const override;
    QList<QCommandLineOption> options() const override;
    int run(CliContext& context, const QStringList& args) override;
};

} // namespace opentop
