#include "cli/CliCommands.h"
#include "cli/NameCommand.h"
#include "cli/ScanCommand.h"

namespace opentop {

void addScanCommands(CliCommandList& list)
{
    list.push_back(std::make_unique<ScanCommand>());
    list.push_back(std::make_unique<NameCommand>());
}

} // namespace opentop
