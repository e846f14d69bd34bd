#pragma once

#include "cli/CliCommand.h"

namespace opentop {

// `ports`: serial ports with their adapter descriptions.
class PortsCommand : public CliCommand
{
public:
    QString name() const override { return QStringLiteral("ports"); }
    QString synopsis() const override { return QStringLiteral("ports"); }
    QString summary() const override;
    int run(CliContext& context, const QStringList& args) override;
};

} // namespace opentop
