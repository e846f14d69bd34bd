#include "cli/BackupCommand.h"
#include "cli/CliCommands.h"
#include "cli/CompareCommand.h"
#include "cli/RestoreCommand.h"

namespace opentop {

void addFileCommands(CliCommandList& list)
{
    list.push_back(std::make_unique<BackupCommand>());
    list.push_back(std::make_unique<RestoreCommand>());
    list.push_back(std::make_unique<CompareCommand>());
}

} // namespace opentop
