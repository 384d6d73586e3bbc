// impactbench: list, describe and run the benchmark scenarios (contract: design.md, "The
// command-line contract"). Every failure ends as one line on stderr and a non-zero exit code
// (see command.hpp).
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "lib/output/message_text.hpp"
#include "tools/cli/blas_threads.hpp"
#include "tools/cli/command.hpp"
#include "tools/cli/sensitivity_command.hpp"
#include "tools/cli/sweep_command.hpp"

namespace {
/// One line on stderr whatever the message holds (it may quote a file or an argument).
void print_error(const char* message) {
  std::cerr << "impactbench: " << impactbench::output::printable(message, 600) << '\n';
}
}  // namespace

int main(int argc, char** argv) {
  using namespace impactbench::cli;
  restart_with_one_blas_thread(argv);
  CLI::App app{"impactbench: accuracy and speed of impact simulation methods"};
  app.require_subcommand(1);
  std::vector<std::unique_ptr<Command>> commands;
  commands.push_back(add_list_command(app));
  commands.push_back(add_describe_command(app));
  commands.push_back(add_run_command(app));
  commands.push_back(add_compare_command(app));
  commands.push_back(add_suite_command(app));
  commands.push_back(add_solve_command(app));
  commands.push_back(add_sensitivity_command(app));
  commands.push_back(add_sweep_command(app));
  commands.push_back(add_merge_command(app));
  commands.push_back(add_sweep_point_command(app));
  commands.push_back(add_validate_command(app));
  commands.push_back(add_settings_page_command(app));

  // CLI11 would only say "a subcommand is required" for a mistyped command; name it instead.
  if (argc > 1 && argv[1][0] != '-') {
    std::string names;
    bool known = false;
    for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
      known = known || sub->get_name() == argv[1];
      if (!sub->get_group().empty())  // hidden commands stay unlisted
        names += (names.empty() ? "" : ", ") + sub->get_name();
    }
    if (!known) {
      print_error(
          ("unknown command '" + std::string(argv[1]) + "' (commands: " + names + ")").c_str());
      return kExitUsage;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    if (error.get_exit_code() == 0) return app.exit(error);  // --help
    std::cerr << "impactbench: " << impactbench::output::printable(error.what(), 600)
              << " (see --help)\n";
    return kExitUsage;
  }
  try {
    for (const auto& command : commands)
      if (command->selected()) return command->run();
  } catch (const CliError& error) {
    print_error(error.what());
    return error.exit_code();
  } catch (const std::bad_alloc&) {
    print_error("out of memory (the run or the file needs more memory than is available)");
    return kExitFailure;
  } catch (const std::exception& error) {
    print_error(error.what());
    return kExitFailure;
  }
  return kExitUsage;
}
