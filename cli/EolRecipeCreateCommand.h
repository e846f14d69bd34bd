#pragma once

#include "EolSubcommand.h"

#include <QVector>
#include <optional>

namespace opentop {

class BackupDevice;

// `eol recipe create (--from-backup FILE | --drives LIST) --product P --revision R -o FILE`:
// a recipe from a golden unit (a backup file, or its drives read off the bus), with the
// family's default test steps, checked and written atomically; an existing file only with
// --force.
class EolRecipeCreateCommand : public EolSubcommand
{
public:
    QString name() const override { return QStringLiteral("recipe create"); }
    QString synopsis() const override
    {
        return QStringLiteral("recipe create (--from-backup FILE | --drives LIST) --product NAME "
                              "--revision REV -o RECIPE [--force]");
    }
    QString summary() const override;
    QList<QCommandLineOption> options() const override;
    int run(CliContext& context, const QStringList& args) override;

private:
    // The golden drives' settings read off the bus, each with its variant read, proven by the
    // profile's probe or given with --variant (how, in `notes`); nullopt (with *exitCode) when
    // one failed or its variant is not known.
    static std::optional<QVector<BackupDevice>>
    readDrives(CliContext& context, const QVector<int>& ids, int* exitCode, QStringList* notes);
};

} // namespace opentop
