#include "CliCommands.h"

namespace opentop {

// Being written: replaced by the drive commands.
void addDriveCommands(CliCommandList&) {}

} // namespace opentop
