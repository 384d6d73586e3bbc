#include "tools/python/bindings/interrupt.hpp"

#include <pybind11/pybind11.h>

#include "tools/compare/run_process.hpp"

namespace impactbench::python {

bool InterruptPoll::due() {
  // 0.1 s keeps a Ctrl-C answered well within a second at a cost of one clock read per call.
  constexpr auto kInterval = std::chrono::milliseconds(100);
  const auto now = std::chrono::steady_clock::now();
  if (now < next_) return false;
  next_ = now + kInterval;
  return true;
}

void InterruptPoll::poll() {
  if (!due()) return;
  pybind11::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() != 0) throw pybind11::error_already_set();
}

void InterruptPoll::poll_as_interruption() {
  if (!due()) return;
  pybind11::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() != 0) {
    PyErr_Clear();  // raised again as KeyboardInterrupt by the translator (errors.cpp)
    throw compare::ProcessInterrupted("interrupted");
  }
}

}  // namespace impactbench::python
