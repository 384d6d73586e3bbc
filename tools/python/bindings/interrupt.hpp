#pragma once
// Ctrl-C during a long call that runs without the GIL: the call's progress callback (an
// engine's recording.progress, a solver's monitor) calls poll(), which at most every 0.1 s of
// wall time takes the GIL and runs Python's signal handlers (PyErr_CheckSignals). When they
// raise (KeyboardInterrupt on SIGINT), poll throws py::error_already_set holding it: the
// exception unwinds the engine like any failed run and reaches Python unchanged.
#include <chrono>

namespace impactbench::python {

class InterruptPoll {
 public:
  /// Throws pybind11::error_already_set when a signal handler raised. Call without the GIL.
  void poll();
  /// The same for a call that treats exceptions as one part's failure (compare runs several
  /// engines): a raised signal is cleared and thrown as compare::ProcessInterrupted, which
  /// ends the whole call and reaches Python as KeyboardInterrupt (errors.cpp).
  void poll_as_interruption();

 private:
  bool due();  ///< whether 0.1 s have passed since the last check
  std::chrono::steady_clock::time_point next_ = std::chrono::steady_clock::now();
};

}  // namespace impactbench::python
