#pragma once

#include "cli/CliCommand.h"
#include "model/files/RestorePlan.h"

namespace opentop {

class BackupDevice;
class DeviceSession;

// `restore FILE [--ids LIST] [--dry-run] [--yes]`: shows what would change on each drive of the
// file and, with --yes, writes it (see Restorer) and reports parameter by parameter.
class RestoreCommand : public CliCommand
{
public:
    QString name() const override { return QStringLiteral("restore"); }
    QString synopsis() const override
    {
        return QStringLiteral("restore FILE [--ids 1,5-7] [--dry-run] [--yes]");
    }
    QString summary() const override;
    QList<QCommandLineOption> options() const override;
    int run(CliContext& context, const QStringList& args) override;

private:
    static void printPlan(CliContext& context, const RestorePlan& plan, bool report);
    static int exitCodeOf(const RestorePlan& plan);
};

} // namespace opentop
