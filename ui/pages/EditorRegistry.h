#pragma once

namespace opentop {

// Registers the specialised editor pages the profiles can name (groups[].editor):
// runningData, ioTerminals, speedUnits, dcController.
void registerBuiltInEditors();

} // namespace opentop
