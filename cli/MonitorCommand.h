#pragma once

#include "cli/CliCommand.h"

namespace opentop {

// `monitor ID... [--interval MS] [--count N] [--csv FILE] [--give-up SECONDS]`: live values of
// one or more drives, one aligned line per sample and drive (JSON Lines with --json), optionally
// logged to CSV. A lost port is said once and opened again by itself (LinkRecovery).
class MonitorCommand : public CliCommand
{
public:
    QString name() const override { return QStringLiteral("monitor"); }
    QString synopsis() const override
    {
        return QStringLiteral(
            "monitor ID... [--interval MS] [--count N] [--csv FILE] [--give-up SECONDS]");
    }
    QString summary() const override;
    QList<QCommandLineOption> options() const override;
    int run(CliContext& context, const QStringList& args) override;
};

} // namespace opentop
