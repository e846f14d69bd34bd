#pragma once

#include "cli/CliCommand.h"

#include <QVector>
#include <optional>

namespace opentop {

// `backup ID... | --all -o FILE`: reads every setting of the drives and writes one backup file,
// atomically and only when every drive was read completely.
class BackupCommand : public CliCommand
{
public:
    QString name() const override { return QStringLiteral("backup"); }
    QString synopsis() const override { return QStringLiteral("backup ID... | --all -o FILE"); }
    QString summary() const override;
    QList<QCommandLineOption> options() const override;
    int run(CliContext& context, const QStringList& args) override;

private:
    // The machine numbers to back up; nullopt after printing a usage error.
    static std::optional<QVector<int>> selectIds(CliContext& context, const QStringList& args);
    // Every drive on the bus: the connection's known drives, or a scan.
    static QVector<int> allDrives(CliContext& context, bool* interrupted);
    // The port went away mid-backup: one error naming it and why, nothing written.
    static int portLost(CliContext& context, const QString& path, const QString& drive,
                        const QStringList& failures);
};

} // namespace opentop
