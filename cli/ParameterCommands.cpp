#include "CliCommands.h"
#include "GetCommand.h"
#include "ParamsCommand.h"
#include "PortsCommand.h"
#include "SetCommand.h"

namespace opentop {

void addParameterCommands(CliCommandList& list)
{
    list.push_back(std::make_unique<PortsCommand>());
    list.push_back(std::make_unique<ParamsCommand>());
    list.push_back(std::make_unique<GetCommand>());
    list.push_back(std::make_unique<SetCommand>());
}

} // namespace opentop
