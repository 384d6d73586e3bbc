// impactbench._impactbench: the compiled half of the Python package `impactbench`
// (tools/python/impactbench/__init__.py wraps it with documented signatures and result types).
#include <pybind11/pybind11.h>

#include "tools/python/bindings/bindings.hpp"
#include "tools/python/bindings/errors.hpp"

PYBIND11_MODULE(_impactbench, m) {
  m.doc() =
      "impactbench's library (scenarios, engines, compare, solvers, sensitivity); use the "
      "package impactbench, which documents each function.";
  impactbench::python::register_errors(m);
  impactbench::python::add_scenario_functions(m);
  impactbench::python::add_run_function(m);
  impactbench::python::add_compare_function(m);
  impactbench::python::add_solver_functions(m);
  impactbench::python::add_sensitivity_function(m);
}
