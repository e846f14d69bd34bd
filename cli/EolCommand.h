#pragma once

#include "cli/CliCommand.h"
#include "cli/EolSubcommand.h"

#include <memory>
#include <vector>

namespace opentop {

// `eol SUBCOMMAND ...`: the end-of-line station's commands (recipes, results, certificates),
// each an EolSubcommand. Picks the subcommand named by the first words, refuses the options
// that are another subcommand's, and lists them all in `opentop-cli help eol`.
class EolCommand : public CliCommand
{
public:
    EolCommand();
    ~EolCommand() override;

    QString name() const override { return QStringLiteral("eol"); }
    QString synopsis() const override;
    QString summary() const override;
    QString details() const override;
    QList<QCommandLineOption> options() const override;
    int run(CliContext& context, const QStringList& args) override;

    void add(std::unique_ptr<EolSubcommand> subcommand);

private:
    EolSubcommand* find(const QStringList& args) const;
    QString names() const; // "recipe create, recipe check, ..."

    std::vector<std::unique_ptr<EolSubcommand>> m_subcommands;
};

} // namespace opentop
