#pragma once

#include "cli/CliCommand.h"

namespace opentop {

// `get ID NAME... | --group G | --all`, and `get ID --raw ADDR[:COUNT] [--fc 3|4]` for
// service work by register address.
class GetCommand : public CliCommand
{
public:
    QString name() const override { return QStringLiteral("get"); }
    QString synopsis() const override
    {
        return QStringLiteral("get ID NAME... | --group G | --all");
    }
    QString summary() const override;
    QList<QCommandLineOption> options() const override;
    int run(CliContext& context, const QStringList& args) override;

private:
    int runRaw(CliContext& context, int slave);
};

} // namespace opentop
