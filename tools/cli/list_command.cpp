// `impactbench list`: the scenario names, one per line.
#include <iostream>

#include "lib/scenario/scenario.hpp"
#include "tools/cli/command.hpp"

namespace impactbench::cli {

namespace {
class ListCommand : public Command {
 public:
  using Command::Command;
  int run() override {
    for (const auto& name : scenario::list_scenarios()) std::cout << name << '\n';
    return 0;
  }
};
}  // namespace

std::unique_ptr<Command> add_list_command(CLI::App& app) {
  return std::make_unique<ListCommand>(
      app.add_subcommand("list", "List the scenario names, one per line"));
}

}  // namespace impactbench::cli
