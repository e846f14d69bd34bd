#include "cli/CliCommands.h"
#include "cli/GetCommand.h"
#include "cli/ParamsCommand.h"
#include "cli/PortsCommand.h"
#include "cli/SetCommand.h"

namespace opentop {

void addParameterCommands(CliCommandList& list)
{
    list.push_back(std::make_unique<PortsCommand>());
    list.push_back(std::make_unique<ParamsCommand>());
    list.push_back(std::make_unique<GetCommand>());
    list.push_back(std::make_unique<SetCommand>());
}

} // namespace opentop
