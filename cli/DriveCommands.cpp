#include "cli/AlarmsCommand.h"
#include "cli/CliCommands.h"
#include "cli/MonitorCommand.h"
#include "cli/RunCommand.h"
#include "cli/StopAllCommand.h"
#include "cli/TuneCommand.h"

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
