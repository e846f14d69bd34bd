#pragma once

#include "cli/CliCommand.h"

namespace opentop {

// `set ID NAME=VALUE...`: every value is validated against the profile before anything is
// sent; each write is read back and verified. `set ID --raw ADDR=VALUE` for service work.
class SetCommand : public CliCommand
{
public:
    QString name() const override { return QStringLiteral("set"); }
    QString synopsis() const override { return QStringLiteral("set ID NAME=VALUE..."); }
    QString summary() const override;
    QList<QCommandLineOption> options() const override;
    int run(CliContext& context, const QStringList& args) override;
};

} // namespace opentop
