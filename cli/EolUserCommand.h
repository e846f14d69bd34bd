#pragma once

#include "cli/EolSubcommand.h"

namespace opentop {

// `eol user add|list|disable|passwd`: the users of the results database (access/AccessCheck
// decides who may; this only parses and shows). One instance per action.
class EolUserCommand : public EolSubcommand
{
public:
    enum class Action
    {
        Add,
        List,
        Disable,
        Passwd
    };
    explicit EolUserCommand(Action action);

    QString name() const override;
    QString synopsis() const override;
    QString summary() const override;
    QList<QCommandLineOption> options() const override;
    int run(CliContext& context, const QStringList& args) override;

private:
    int list(CliContext& context);
    Action m_action;
};

} // namespace opentop
