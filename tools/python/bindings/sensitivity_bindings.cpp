// sensitivity(): the jump gains and end-point matrices `impactbench sensitivity` writes to its
// CSV, as numpy arrays, from the same linearisation (cli::SensitivityStudy) in the same reported
// coordinates (lib/sensitivity/reported_coordinates.hpp), with the coordinates' names.
#include <pybind11/stl.h>

#include "lib/sensitivity/conewise_jump_gain.hpp"
#include "lib/sensitivity/reported_coordinates.hpp"
#include "tools/cli/command.hpp"
#include "tools/cli/overrides.hpp"
#include "tools/cli/sensitivity_study.hpp"
#include "tools/cli/setting_flags.hpp"
#include "tools/engines/registry/scenario_loading.hpp"
#include "tools/python/bindings/arguments.hpp"
#include "tools/python/bindings/arrays.hpp"
#include "tools/python/bindings/bindings.hpp"
#include "tools/python/bindings/errors.hpp"

namespace py = pybind11;

namespace impactbench::python {
namespace {

py::dict sensitivity(const std::string& name, std::optional<double> duration,
                     std::optional<double> tol, const py::dict& set, bool parameter_gains) {
  check_flag("--duration", cli::kPositiveFinite, duration);
  check_flag("--tol", cli::kPositiveFinite, tol);
  auto s = scenario::load_scenario_by_name(name, cli::parse_overrides(assignments(set, "--set")),
                                           duration);
  std::unique_ptr<cli::SensitivityStudy> study;
  sensitivity::EndPointSensitivity end_point;
  {
    py::gil_scoped_release unlocked;
    study = std::make_unique<cli::SensitivityStudy>(std::move(s), duration, tol, parameter_gains);
    end_point = sensitivity::reported_end_point(study->linearisation(), study->end_point());
  }
  const sensitivity::TrajectorySensitivity& linearisation = study->linearisation();
  py::list events;
  const auto& cones = linearisation.events();
  for (std::size_t k = 0; k < cones.size(); ++k) {
    py::list gains;
    for (sensitivity::ComposedGain& composed : cones[k].all_gains()) {
      sensitivity::ComposedGain gain =
          sensitivity::reported_gain(linearisation.model(), cones[k], std::move(composed));
      py::list micro_events;
      for (const int i : gain.order)
        micro_events.append(to_string(cones[k].events()[static_cast<std::size_t>(i)]));
      gains.append(py::dict(py::arg("order") = gain.order, py::arg("micro_events") = micro_events,
                            py::arg("Gz") = take_array(std::move(gain.Gz)),
                            py::arg("Gv") = take_array(std::move(gain.Gv))));
    }
    events.append(py::dict(py::arg("index") = k,
                           py::arg("t") = linearisation.nominal().events[k].time,
                           py::arg("gains") = gains));
  }
  py::list state_names;
  for (const auto& n : sensitivity::reported_state_names(
           linearisation.model(), study->built().system->position_names(),
           study->built().system->velocity_names(), study->model().num_parameters()))
    state_names.append(n);
  py::dict out;
  out["scenario"] = study->scenario().name;
  out["state_names"] = state_names;
  out["events"] = events;
  out["t_end"] = linearisation.nominal().t_end;
  out["end_point_state"] = take_array(std::move(end_point.state));
  out["end_point_input"] = take_array(std::move(end_point.input));
  return out;
}

}  // namespace

void add_sensitivity_function(py::module_& m) {
  m.def("_sensitivity", &sensitivity, py::arg("name"), py::arg("duration") = py::none(),
        py::arg("tol") = py::none(), py::arg("set") = py::dict(),
        py::arg("parameter_gains") = false);
}

}  // namespace impactbench::python
