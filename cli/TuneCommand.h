#pragma once

#include "cli/CliCommand.h"

namespace opentop {

class TuningRunner;
struct PidGains;

// `tune ID step|autotune ... --yes`: the speed-loop step test and relay autotune of a drive whose
// profile can be tuned (TuningRunner), headless, with a report. Gains are written only with
// --accept and stored only with --store; without --accept the drive keeps the gains it had.
class TuneCommand : public CliCommand
{
public:
    QString name() const override { return QStringLiteral("tune"); }
    QString synopsis() const override
    {
        return QStringLiteral("tune ID step --from A --to B | autotune --speed S [--accept "
                              "[--store]] --yes");
    }
    QString summary() const override;
    QList<QCommandLineOption> options() const override;
    int run(CliContext& context, const QStringList& args) override;
};

} // namespace opentop
