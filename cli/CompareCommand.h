#pragma once

#include "cli/CliCommand.h"
#include "model/files/BackupDevice.h"

#include <optional>

namespace opentop {

// `compare A B | A --defaults`: the settings that differ between two backups, drives, or a
// backup or drive and the factory defaults. Each side is a machine number (read live), a
// backup file, or FILE:ID for a file with several drives. Exit 0 whether or not they differ.
class CompareCommand : public CliCommand
{
public:
    QString name() const override { return QStringLiteral("compare"); }
    QString synopsis() const override { return QStringLiteral("compare A B | A --defaults"); }
    QString summary() const override;
    QList<QCommandLineOption> options() const override;
    int run(CliContext& context, const QStringList& args) override;

private:
    struct Side
    {
        QString label; // "backup.json:1", "drive 1"
        BackupDevice device;
    };
    // A machine number, FILE or FILE:ID; nullopt after printing why, with *code set.
    static std::optional<Side> resolve(CliContext& context, const QString& text, int* code);
    static std::optional<Side> readDrive(CliContext& context, int slave, int* code);
};

} // namespace opentop
