#pragma once
// Child processes of `compare` and `suite` (plot scripts, benchmark binaries). While one runs,
// Ctrl-C (SIGINT) or SIGTERM is forwarded to it — `timeout` puts benchmarks in their own
// process group, out of the terminal's reach — and the files it was writing are removed if it
// did not finish, so an interrupted suite leaves no truncated PNG or JSON behind.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace impactbench::compare {

/// Thrown after a child was stopped because this process was interrupted.
struct ProcessInterrupted : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Runs argv[0] with the arguments (no shell) and waits; returns its exit status, or -1 when it
/// could not be started or was killed by a signal. `outputs` are removed unless it exited with
/// status 0. Throws ProcessInterrupted when SIGINT or SIGTERM arrived meanwhile.
int run_process(const std::vector<std::string>& argv,
                const std::vector<std::filesystem::path>& outputs = {});

}  // namespace impactbench::compare
