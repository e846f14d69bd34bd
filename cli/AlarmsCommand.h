#pragma once

#include "cli/CliCommand.h"

namespace opentop {

// `alarms ID [--reset] [--clear-records] [--yes]`: the alarm and warning histories with cause
// and remedy, the communication error register; alarm reset and erasing the records.
class AlarmsCommand : public CliCommand
{
public:
    QString name() const override { return QStringLiteral("alarms"); }
    QString synopsis() const override
    {
        return QStringLiteral("alarms ID [--reset] [--clear-records] [--yes]");
    }
    QString summary() const override;
    QList<QCommandLineOption> options() const override;
    int run(CliContext& context, const QStringList& args) override;
};

} // namespace opentop
