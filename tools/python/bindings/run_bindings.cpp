// run(): `impactbench run` with the trajectory in numpy arrays instead of a CSV. The same
// request (cli::prepare_run: scenario, engine, settings, sample interval), the same sampling
// (cli::run_recording) and the same engine call; the samples go into contiguous buffers that
// become the arrays without a copy.
#include <cmath>
#include <map>

#include <pybind11/stl.h>
#include <CLI/CLI.hpp>

#include "lib/metrics/run_figures.hpp"
#include "tools/cli/run_request.hpp"
#include "tools/cli/setting_flags.hpp"
#include "tools/python/bindings/arguments.hpp"
#include "tools/python/bindings/arrays.hpp"
#include "tools/python/bindings/bindings.hpp"
#include "tools/python/bindings/errors.hpp"
#include "tools/python/bindings/interrupt.hpp"

namespace py = pybind11;

namespace impactbench::python {
namespace {

/// The kept samples, row after row, as the trajectory CSV holds them.
struct SampleBuffers {
  std::vector<double> t, q, v, energy;
  void add(const output::TrajectorySample& sample) {
    t.push_back(sample.t);
    q.insert(q.end(), sample.q.data(), sample.q.data() + sample.q.size());
    v.insert(v.end(), sample.v.data(), sample.v.data() + sample.v.size());
    energy.push_back(sample.energy);
  }
};

py::dict events_columns(const std::vector<output::EventRecord>& events) {
  std::vector<double> t, impulse_n, impulse_t;
  py::list contact, kind, from_mode, to_mode;
  for (const auto& e : events) {
    t.push_back(e.t);
    impulse_n.push_back(e.impulse_n);
    impulse_t.push_back(e.impulse_t);
    contact.append(e.contact);
    kind.append(e.kind);
    from_mode.append(e.from_mode);
    to_mode.append(e.to_mode);
  }
  const auto n = static_cast<py::ssize_t>(events.size());
  py::dict out;
  out["t"] = take_array(std::move(t), {n});
  out["contact"] = contact;
  out["kind"] = kind;
  out["from_mode"] = from_mode;
  out["to_mode"] = to_mode;
  out["impulse_n"] = take_array(std::move(impulse_n), {n});
  out["impulse_t"] = take_array(std::move(impulse_t), {n});
  return out;
}

/// What the run summary of `impactbench run` prints (tools/cli/run_summary.cpp), as values.
py::dict summary_of(const scenario::Scenario& s, const engines::RunOptions& options,
                    const engines::RunResult& result) {
  py::dict out;
  out["engine"] = result.engine;
  out["scenario"] = s.name;
  out["duration"] = options.duration;
  out["duration_source"] = engines::to_string(options.duration_source);
  py::list settings;
  for (const auto& setting : result.settings)
    settings.append(py::dict(py::arg("key") = setting.key, py::arg("value") = setting.value,
                             py::arg("source") = engines::to_string(setting.source)));
  out["settings"] = settings;
  out["samples"] = result.sample_count;
  // The figures of metrics.csv under their names; None where the engine has no tolerance.
  for (const auto& [name, value] : metrics::run_figures(result))
    out[py::str(name)] = std::isnan(value) ? py::object(py::none()) : py::object(py::float_(value));
  out["unconverged_note"] = result.unconverged_note;
  out["defect_note"] = result.defect_note;
  out["worst_unconverged_residual"] = result.worst_unconverged_residual;
  std::map<std::string, int> kinds;
  for (const auto& event : result.events) ++kinds[event.kind];
  out["events"] = result.events.size();
  out["event_kinds"] = kinds;
  out["max_penetration"] = result.max_penetration;
  out["first_energy"] = result.first_energy;
  out["last_energy"] = result.last_energy;
  py::dict engine_summary;
  for (const auto& [key, value] : result.summary) engine_summary[py::str(key)] = value;
  out["engine_summary"] = engine_summary;
  return out;
}

py::dict run(const std::string& name, const std::string& engine, std::optional<double> dt,
             std::optional<double> tol, std::optional<std::string> solver,
             std::optional<double> duration, const py::dict& set, const py::dict& options,
             std::optional<double> sample_dt, const std::string& settings) {
  // The option checks of the command line, in its order, before anything is loaded.
  check_flag("--engine", CLI::IsMember(adapters::engine_names()), engine);
  check_flag("--dt", cli::kPositiveFinite, dt);
  check_flag("--tol", cli::kPositiveFinite, tol);
  check_flag("--duration", cli::kPositiveFinite, duration);
  check_flag("--sample-dt", cli::kNonNegativeFinite, sample_dt);
  check_flag("--settings", cli::kSettingsSetName, settings);
  const cli::RunRequest request{name,
                                engine,
                                dt,
                                tol,
                                solver,
                                duration,
                                assignments(set, "--set"),
                                assignments(options, "--option"),
                                sample_dt,
                                settings};
  cli::PreparedRun prepared = cli::prepare_run(request);
  const adapters::EngineInfo& info = cli::built_engine(engine);

  SampleBuffers buffers;
  InterruptPoll interrupt;
  engines::RunOptions& run_options = prepared.options;
  run_options.recording = cli::run_recording(engine, run_options.duration, sample_dt);
  run_options.recording.sample_sink = [&buffers](const output::Trajectory&,
                                                 const output::TrajectorySample& sample) {
    buffers.add(sample);
  };
  run_options.recording.progress = [&interrupt](double) { interrupt.poll(); };
  engines::RunResult result;
  {
    py::gil_scoped_release unlocked;
    result = info.run(prepared.scenario, run_options);
  }
  const auto rows = static_cast<py::ssize_t>(buffers.t.size());
  const auto nq = static_cast<py::ssize_t>(result.trajectory.position_names.size());
  const auto nv = static_cast<py::ssize_t>(result.trajectory.velocity_names.size());
  py::dict out;
  out["t"] = take_array(std::move(buffers.t), {rows});
  out["q"] = take_array(std::move(buffers.q), {rows, nq});
  out["v"] = take_array(std::move(buffers.v), {rows, nv});
  out["energy"] = take_array(std::move(buffers.energy), {rows});
  out["position_names"] = result.trajectory.position_names;
  out["velocity_names"] = result.trajectory.velocity_names;
  out["events"] = events_columns(result.events);
  out["summary"] = summary_of(prepared.scenario, run_options, result);
  return out;
}

}  // namespace

void add_run_function(py::module_& m) {
  m.def("_run", &run, py::arg("name"), py::arg("engine"), py::arg("dt") = py::none(),
        py::arg("tol") = py::none(), py::arg("solver") = py::none(),
        py::arg("duration") = py::none(), py::arg("set") = py::dict(),
        py::arg("options") = py::dict(), py::arg("sample_dt") = py::none(),
        py::arg("settings") = "default",
        "Internal: impactbench.run returns its result as a RunResult.");
}

}  // namespace impactbench::python
