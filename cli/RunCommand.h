#pragma once

#include "cli/CliCommand.h"

namespace opentop {

// `run ID start|stop|cw|ccw|select N|hold|free|coast|speed VALUE --yes`: one test-run command,
// sent only with --yes and only to a drive that takes motion commands over the bus; then the
// drive's state as read back.
class RunCommand : public CliCommand
{
public:
    QString name() const override { return QStringLiteral("run"); }
    QString synopsis() const override
    {
        return QStringLiteral("run ID start|stop|cw|ccw|select N|hold|free|coast|speed V --yes");
    }
    QString summary() const override;
    QList<QCommandLineOption> options() const override;
    int run(CliContext& context, const QStringList& args) override;
};

} // namespace opentop
