#include "CliCommands.h"

namespace opentop {

// Being written: replaced by the file commands.
void addFileCommands(CliCommandList&) {}

} // namespace opentop
