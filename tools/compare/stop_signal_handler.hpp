#pragma once
// SIGINT and SIGTERM handled by one function while an object of this class lives, the previous
// handlers restored when it ends: a child process run by compare (run_process) and the sweep's
// worker pool each install theirs around the children they wait for.
#include <csignal>

namespace impactbench::compare {

class StopSignalHandler {
 public:
  explicit StopSignalHandler(void (*handler)(int)) {
    struct sigaction action {};
    action.sa_handler = handler;
    sigemptyset(&action.sa_mask);
    ::sigaction(SIGINT, &action, &previous_int_);
    ::sigaction(SIGTERM, &action, &previous_term_);
  }
  ~StopSignalHandler() {
    ::sigaction(SIGINT, &previous_int_, nullptr);
    ::sigaction(SIGTERM, &previous_term_, nullptr);
  }
  StopSignalHandler(const StopSignalHandler&) = delete;
  StopSignalHandler& operator=(const StopSignalHandler&) = delete;

 private:
  struct sigaction previous_int_ {};
  struct sigaction previous_term_ {};
};

}  // namespace impactbench::compare
