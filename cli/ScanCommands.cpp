#include "CliCommands.h"
#include "NameCommand.h"
#include "ScanCommand.h"

namespace opentop {

void addScanCommands(CliCommandList& list)
{
    list.push_back(std::make_unique<ScanCommand>());
    list.push_back(std::make_unique<NameCommand>());
}

} // namespace opentop
