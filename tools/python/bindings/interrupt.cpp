#include "tools/python/bindings/interrupt.hpp"

#include <pybind11/pybind11.h>

namespace impactbench::python {

void InterruptPoll::poll() {
  // 0.1 s keeps a Ctrl-C answered well within a second at a cost of one clock read per call.
  constexpr auto kInterval = std::chrono::milliseconds(100);
  const auto now = std::chrono::steady_clock::now();
  if (now < next_) return;
  next_ = now + kInterval;
  pybind11::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() != 0) throw pybind11::error_already_set();
}

}  // namespace impactbench::python
