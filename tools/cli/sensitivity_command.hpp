#pragma once
// The `sensitivity` subcommand (tools/cli/sensitivity_command.cpp). Registered in main.cpp
// like the others: commands.push_back(add_sensitivity_command(app)).
#include <memory>

#include "tools/cli/command.hpp"

namespace impactbench::cli {

std::unique_ptr<Command> add_sensitivity_command(CLI::App& app);

}  // namespace impactbench::cli
