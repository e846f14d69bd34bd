#include "cli/CliCommands.h"

namespace opentop {

CliCommandList makeCliCommands()
{
    CliCommandList list;
    addParameterCommands(list);
    addScanCommands(list);
    addFileCommands(list);
    addDriveCommands(list);
    addEolCommands(list);
    return list;
}

} // namespace opentop
