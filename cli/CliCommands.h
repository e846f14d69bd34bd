#pragma once

#include "cli/CliCommand.h"

#include <memory>
#include <vector>

namespace opentop {

using CliCommandList = std::vector<std::unique_ptr<CliCommand>>;

// Every command, in the order `--help` lists them. Each group lives with its commands.
CliCommandList makeCliCommands();
void addParameterCommands(CliCommandList& list); // ports, params, get, set
void addScanCommands(CliCommandList& list);      // scan, name
void addFileCommands(CliCommandList& list);      // backup, restore, compare
void addDriveCommands(CliCommandList& list);     // monitor, alarms, run, stop-all
void addEolCommands(CliCommandList& list);       // eol (recipes, results, certificates)

} // namespace opentop
