// scenarios() and describe(): what `impactbench list` and `impactbench describe` print, as
// Python values.
#include <filesystem>

#include <pybind11/stl.h>

#include "lib/output/number_text.hpp"
#include "lib/resources/resource_paths.hpp"
#include "lib/scenario/scenario.hpp"
#include "tools/cli/overrides.hpp"
#include "tools/engines/registry/run_settings.hpp"
#include "tools/engines/registry/scenario_loading.hpp"
#include "tools/python/bindings/arguments.hpp"
#include "tools/python/bindings/bindings.hpp"

namespace py = pybind11;

namespace impactbench::python {
namespace {

py::list names_of(const auto& items) {
  py::list names;
  for (const auto& item : items) names.append(item.name);
  return names;
}

py::dict describe(const std::string& name, const py::dict& set) {
  const auto s =
      scenario::load_scenario_by_name(name, cli::parse_overrides(assignments(set, "--set")));
  py::dict out;
  out["name"] = s.name;
  out["description"] = s.description;
  out["file"] = s.path.string();
  out["dimension"] = to_string(s.dimension);
  out["system"] = to_string(s.system);
  out["engines"] = s.engines;
  out["duration"] = s.duration;
  out["dt"] = s.dt;
  out["tolerance"] = s.tolerance;
  out["bodies"] = names_of(s.bodies);
  out["planes"] = names_of(s.planes);
  py::list inputs;
  for (const auto& input : s.inputs) inputs.append("force on " + input.body);
  out["inputs"] = inputs;
  py::list parameters;
  for (const auto& p : s.parameters)
    parameters.append(py::dict(py::arg("name") = p.name, py::arg("value") = p.value,
                               py::arg("default") = p.default_value, py::arg("unit") = p.unit,
                               py::arg("description") = p.description));
  out["parameters"] = parameters;
  // Each engine's settings as `run` would use them: defaults, then the scenario's.
  py::dict settings;
  for (const std::string& engine : s.engines) {
    py::list entries;
    for (const auto& setting : engines::resolve_run_options(engine, s).settings)
      entries.append(py::dict(py::arg("key") = setting.key, py::arg("value") = setting.value,
                              py::arg("source") = engines::to_string(setting.source)));
    settings[py::str(engine)] = entries;
  }
  out["settings"] = settings;
  py::list analytic;
  for (const auto& q : s.analytic_quantities)
    analytic.append(py::dict(py::arg("name") = q.name, py::arg("value") = s.analytic(q.name, 0),
                             py::arg("unit") = q.unit, py::arg("indexed") = q.indexed,
                             py::arg("description") = q.description,
                             py::arg("expression") = q.expression));
  out["analytic"] = analytic;
  return out;
}

}  // namespace

void add_scenario_functions(py::module_& m) {
  m.def(
      "_set_package_directory",
      [](const std::string& package) {
        const std::filesystem::path prefix =
            (std::filesystem::path(package) / IMPACTBENCH_PACKAGE_TO_PREFIX).lexically_normal();
        resources::set_program_directory(prefix / "bin");
      },
      "Internal: the package's folder, below the prefix where share/impactbench is found.");
  m.def("scenarios", &scenario::list_scenarios,
        "The scenario names, as `impactbench list` prints them (sorted).");
  m.def("describe", &describe, py::arg("name"), py::arg("set") = py::dict(),
        R"(What `impactbench describe NAME [--set k=v]...` prints, as a dict.

Keys: name, description, file, dimension, system, engines, duration [s], dt [s], tolerance,
bodies, planes, inputs; parameters (list of dicts: name, value, default, unit, description);
settings ({engine: [{key, value, source}]}, the settings in force per engine with their source);
analytic (list of dicts: name, value (at k = 0 when indexed), unit, indexed, description,
expression). `set` overrides parameters ({"restitution": 0.5}). Raises impactbench.Error with
the program's message for an unknown scenario or a bad override.)");
}

}  // namespace impactbench::python
