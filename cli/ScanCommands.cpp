#include "CliCommands.h"

namespace opentop {

// Being written: replaced by the scan commands.
void addScanCommands(CliCommandList&) {}

} // namespace opentop
