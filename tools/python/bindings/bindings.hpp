#pragma once
// The Python module `impactbench._impactbench`, one file per area; module.cpp calls each
// add_* on the module. Every function calls the library code the program calls (tools/cli's
// request functions, the engine registry, compare, the solvers): the module converts
// arguments and results, and adds nothing to the numerics.
#include <pybind11/pybind11.h>

namespace impactbench::python {

void add_scenario_functions(pybind11::module_& m);    ///< scenarios, describe
void add_run_function(pybind11::module_& m);          ///< run
void add_compare_function(pybind11::module_& m);      ///< compare
void add_solver_functions(pybind11::module_& m);      ///< solve_lcp, solve_friction, read_*
void add_sensitivity_function(pybind11::module_& m);  ///< sensitivity

}  // namespace impactbench::python
