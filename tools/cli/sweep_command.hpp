#pragma once
// The sweep commands (sweep_command.cpp): `sweep`, `merge` and the hidden `sweep-point`.
#include <memory>

#include "tools/cli/command.hpp"

namespace impactbench::cli {

std::unique_ptr<Command> add_sweep_command(CLI::App& app);
std::unique_ptr<Command> add_merge_command(CLI::App& app);
std::unique_ptr<Command> add_sweep_point_command(CLI::App& app);

}  // namespace impactbench::cli
