// impactbench: list, describe and run the benchmark scenarios (contract: design.md, "The
// command-line contract"). Every failure ends as one line on stderr and a non-zero exit code
// (see command.hpp).
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "tools/cli/command.hpp"

int main(int argc, char** argv) {
  using namespace impactbench::cli;
  CLI::App app{"impactbench: accuracy and speed of impact simulation methods"};
  app.require_subcommand(1);
  std::vector<std::unique_ptr<Command>> commands;
  commands.push_back(add_list_command(app));
  commands.push_back(add_describe_command(app));
  commands.push_back(add_run_command(app));
  commands.push_back(add_compare_command(app));
  commands.push_back(add_suite_command(app));

  // CLI11 would only say "a subcommand is required" for a mistyped command; name it instead.
  if (argc > 1 && argv[1][0] != '-') {
    std::string names;
    bool known = false;
    for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
      known = known || sub->get_name() == argv[1];
      names += (names.empty() ? "" : ", ") + sub->get_name();
    }
    if (!known) {
      std::cerr << "impactbench: unknown command '" << argv[1] << "' (commands: " << names << ")\n";
      return kExitUsage;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    if (error.get_exit_code() == 0) return app.exit(error);  // --help
    std::cerr << "impactbench: " << error.what() << " (see --help)\n";
    return kExitUsage;
  }
  try {
    for (const auto& command : commands)
      if (command->selected()) return command->run();
  } catch (const CliError& error) {
    std::cerr << "impactbench: " << error.what() << '\n';
    return error.exit_code();
  } catch (const std::exception& error) {
    std::cerr << "impactbench: " << error.what() << '\n';
    return kExitFailure;
  }
  return kExitUsage;
}
