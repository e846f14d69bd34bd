#pragma once

#include "cli/CliCommand.h"

namespace opentop {

// `name [ID [TEXT]]`: the names users give the machines of a bus ("Infeed conveyor 3"), kept
// per bus like the window's (BusMemory): without ID every name of the bus, with ID that
// machine's, with TEXT sets it ("" removes it). Names are checked by the model (DriveName); the
// bus is not opened: a machine that is switched off can be named too.
class NameCommand : public CliCommand
{
public:
    QString name() const override { return QStringLiteral("name"); }
    QString synopsis() const override { return QStringLiteral("name [ID [TEXT]]"); }
    QString summary() const override;
    int run(CliContext& context, const QStringList& args) override;
};

} // namespace opentop
