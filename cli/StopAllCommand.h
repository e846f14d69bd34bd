#pragma once

#include "cli/CliCommand.h"

namespace opentop {

// `stop-all --yes [--ids LIST]`: broadcasts every family's stop command, then confirms that
// each known drive has stopped.
class StopAllCommand : public CliCommand
{
public:
    QString name() const override { return QStringLiteral("stop-all"); }
    QString synopsis() const override { return QStringLiteral("stop-all --yes [--ids LIST]"); }
    QString summary() const override;
    QList<QCommandLineOption> options() const override;
    int run(CliContext& context, const QStringList& args) override;
};

} // namespace opentop
