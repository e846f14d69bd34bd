#include "CliCommands.h"
#include "ScanCommand.h"

namespace opentop {

void addScanCommands(CliCommandList& list)
{
    list.push_back(std::make_unique<ScanCommand>());
}

} // namespace opentop
