#include "CliCommands.h"

namespace opentop {

void addParameterCommands(CliCommandList&) {}

} // namespace opentop
