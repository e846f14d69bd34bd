#pragma once

#include <QCommandLineOption>
#include <QList>
#include <QString>
#include <QStringList>

namespace opentop {

class CliContext;

// One opentop-cli command. Commands declare their own options; every option is accepted
// anywhere on the line, and a command refuses options that are not its own.
class CliCommand
{
public:
    virtual ~CliCommand() = default;
    virtual QString name() const = 0;
    virtual QString synopsis() const = 0; // "get ID NAME... | --group G | --all"
    virtual QString summary() const = 0;  // one line for the command list
    virtual QList<QCommandLineOption> options() const { return {}; }
    // More lines for the command's own help (a command with subcommands lists them here).
    virtual QString details() const { return {}; }
    // `args`: positional arguments after the command name. Returns an ExitCode.
    virtual int run(CliContext& context, const QStringList& args) = 0;
};

} // namespace opentop
