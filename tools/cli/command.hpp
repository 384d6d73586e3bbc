#pragma once
// Each subcommand of `impactbench` lives in its own file: a factory registers the subcommand
// and its options on the CLI11 app and returns the object that runs it after parsing.
//
// Exit codes: 0 success; 1 failure (bad scenario or value, engine error, unwritable output);
// 2 usage errors and engines that are not available.
#include <memory>
#include <stdexcept>
#include <string>

#include <CLI/CLI.hpp>

namespace impactbench::cli {

class Command {
 public:
  explicit Command(CLI::App* app) : app_(app) {}
  virtual ~Command() = default;
  /// Whether this subcommand was given on the command line.
  bool selected() const { return app_->parsed(); }
  /// Runs the command; returns the exit code or throws (see CliError).
  virtual int run() = 0;

 private:
  CLI::App* app_;
};

/// An error with its exit code; main prints "impactbench: <message>" as one line on stderr.
class CliError : public std::runtime_error {
 public:
  CliError(const std::string& message, int exit_code)
      : std::runtime_error(message), exit_code_(exit_code) {}
  int exit_code() const { return exit_code_; }

 private:
  int exit_code_;
};

inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;
/// `solve` only: the faceted-cone LCP was solved (its solution is written), but the problem as
/// stated, on the Coulomb disk, is not solved to the tolerance. Never 0: a script that reads the
/// exit code must not take an approximation for a solution.
inline constexpr int kExitFacetedOnly = 3;
/// `compare` only: at least one engine's run failed; metrics.csv is written with its row (the
/// reason in `failure`) beside the measured rows of the engines that ran.
inline constexpr int kExitEngineFailed = 4;

std::unique_ptr<Command> add_list_command(CLI::App& app);
std::unique_ptr<Command> add_describe_command(CLI::App& app);
std::unique_ptr<Command> add_run_command(CLI::App& app);
std::unique_ptr<Command> add_compare_command(CLI::App& app);
std::unique_ptr<Command> add_suite_command(CLI::App& app);
std::unique_ptr<Command> add_solve_command(CLI::App& app);
std::unique_ptr<Command> add_validate_command(CLI::App& app);
std::unique_ptr<Command> add_settings_page_command(CLI::App& app);  ///< hidden: docs/settings.md

}  // namespace impactbench::cli
