#include "AlarmsCommand.h"
#include "CliCommands.h"
#include "MonitorCommand.h"
#include "RunCommand.h"
#include "StopAllCommand.h"
#include "TuneCommand.h"

namespace opentop {

void addDriveCommands(CliCommandList& list)
{
    list.push_back(std::make_unique<MonitorCommand>());
    list.push_back(std::make_unique<AlarmsCommand>());
    list.push_back(std::make_unique<RunCommand>());
    list.push_back(std::make_unique<StopAllCommand>());
    list.push_back(std::make_unique<TuneCommand>());
}

} // namespace opentop
