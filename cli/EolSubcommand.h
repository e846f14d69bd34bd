#pragma once

#include <QCommandLineOption>
#include <QList>
#include <QString>
#include <QStringList>

namespace opentop {

class CliContext;

// One subcommand of `opentop-cli eol` ("recipe check", "results"): like a CliCommand, but
// named by one or two words after `eol`. The `eol` command (EolCommand) offers the union of
// their options and refuses, per subcommand, the options that are not its own.
class EolSubcommand
{
public:
    virtual ~EolSubcommand() = default;
    virtual QString name() const = 0;     // "recipe check"
    virtual QString synopsis() const = 0; // "recipe check RECIPE [--units CSV]"
    virtual QString summary() const = 0;  // one line
    virtual QList<QCommandLineOption> options() const { return {}; }
    // `args`: the positional arguments after the subcommand's name. Returns an ExitCode.
    virtual int run(CliContext& context, const QStringList& args) = 0;
};

} // namespace opentop
