#include "tools/compare/run_process.hpp"
#include "tools/compare/stop_signal_handler.hpp"

#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <csignal>

extern char** environ;

namespace impactbench::compare {

namespace {

volatile std::sig_atomic_t interrupted_by = 0;
volatile pid_t running_child = 0;

extern "C" void forward_to_child(int signal) {
  interrupted_by = signal;
  if (running_child > 0) ::kill(running_child, signal);
}

/// Forwards SIGINT and SIGTERM to the child while alive; restores the previous handlers.
class ForwardSignals {
 public:
  ForwardSignals() : handler_(forward_to_child) { interrupted_by = 0; }
  ~ForwardSignals() { running_child = 0; }
  ForwardSignals(const ForwardSignals&) = delete;
  ForwardSignals& operator=(const ForwardSignals&) = delete;

 private:
  StopSignalHandler handler_;
};

}  // namespace

int run_process(const std::vector<std::string>& argv,
                const std::vector<std::filesystem::path>& outputs) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  int result = -1;
  int signal = 0;
  {
    const ForwardSignals forwarding;
    pid_t pid = 0;
    // The child starts with default handlers: exec resets caught signals.
    if (posix_spawnp(&pid, args[0], nullptr, nullptr, args.data(), environ) == 0) {
      running_child = pid;
      if (interrupted_by != 0) ::kill(pid, interrupted_by);  // arrived before running_child
      int status = 0;
      pid_t waited = -1;
      do {
        waited = ::waitpid(pid, &status, 0);
      } while (waited < 0 && errno == EINTR);
      if (waited == pid && WIFEXITED(status)) result = WEXITSTATUS(status);
    }
    signal = interrupted_by;
  }
  if (result != 0) {
    std::error_code ignored;
    for (const auto& path : outputs) std::filesystem::remove(path, ignored);
  }
  if (signal != 0)
    throw ProcessInterrupted(std::string("interrupted (") +
                             (signal == SIGINT ? "SIGINT" : "SIGTERM") + ") while running " +
                             argv.front() + "; its output was removed");
  return result;
}

}  // namespace impactbench::compare
