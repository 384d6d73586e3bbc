// compare(): `impactbench compare` with its metrics table as columns. The same checks
// (cli::compare_options) and the same comparison (compare::run_compare), which writes its CSV
// files into `out`, or into a temporary folder removed afterwards; no plots.
#include <stdlib.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include <pybind11/stl.h>

#include "tools/cli/command.hpp"
#include "tools/cli/compare_request.hpp"
#include "tools/cli/overrides.hpp"
#include "tools/cli/setting_flags.hpp"
#include "tools/compare/compare.hpp"
#include "tools/engines/registry/scenario_loading.hpp"
#include "tools/python/bindings/arguments.hpp"
#include "tools/python/bindings/arrays.hpp"
#include "tools/python/bindings/bindings.hpp"
#include "tools/python/bindings/errors.hpp"
#include "tools/python/bindings/interrupt.hpp"

namespace py = pybind11;

namespace impactbench::python {
namespace {

namespace fs = std::filesystem;

/// A folder of its own under the system's temporary folder, removed with everything in it.
class TemporaryFolder {
 public:
  TemporaryFolder() {
    std::string pattern = (fs::temp_directory_path() / "impactbench-compare-XXXXXX").string();
    if (!mkdtemp(pattern.data()))
      throw cli::CliError(
          "compare: cannot create a temporary folder in " + fs::temp_directory_path().string(),
          cli::kExitFailure);
    path_ = pattern;
  }
  ~TemporaryFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

py::dict compare(const std::string& name, const std::vector<std::string>& engines,
                 std::optional<double> dt, std::optional<double> duration, const py::dict& set,
                 const py::dict& options, std::optional<std::string> out,
                 const std::string& settings) {
  check_flag("--dt", cli::kPositiveFinite, dt);
  check_flag("--settings", cli::kSettingsSetName, settings);
  check_flag("--duration", cli::kPositiveFinite, duration);
  const auto s =
      scenario::load_scenario_by_name(name, cli::parse_overrides(assignments(set, "--set")));
  std::optional<TemporaryFolder> temporary;
  if (!out) temporary.emplace();
  const fs::path folder = out ? fs::path(*out) : temporary->path();
  compare::CompareOptions compare_options = cli::compare_options(
      s, cli::CompareRequest{engines, dt, duration, assignments(options, "--option"), folder,
                             settings});
  InterruptPoll interrupt;  // Ctrl-C ends the whole comparison, not just one engine's run
  compare_options.progress = [&interrupt](double) { interrupt.poll_as_interruption(); };
  compare::CompareReport report;
  {
    py::gil_scoped_release unlocked;
    report = compare::run_compare(s, compare_options);
  }
  // The columns of metrics.csv: engine, every metric (NaN where it does not apply), failure (why
  // an engine's run failed; its metrics are then NaN, and the others are still measured), note.
  const std::vector<std::string> metric_names = report.metric_names();
  py::dict columns;
  py::list engine_column, failure_column, note_column;
  for (const auto& row : report.rows) {
    engine_column.append(row.engine);
    failure_column.append(row.failure);
    note_column.append(row.note);
  }
  columns["engine"] = engine_column;
  const auto rows = static_cast<py::ssize_t>(report.rows.size());
  for (const std::string& metric : metric_names) {
    std::vector<double> values;
    for (const auto& row : report.rows) values.push_back(compare::named_value(row.values, metric));
    columns[py::str(metric)] = take_array(std::move(values), {rows});
  }
  columns["failure"] = failure_column;
  columns["note"] = note_column;
  py::dict result;
  result["scenario"] = s.name;
  result["reference"] = report.reference;
  result["columns"] = columns;
  return result;
}

}  // namespace

void add_compare_function(py::module_& m) {
  m.def("_compare", &compare, py::arg("name"), py::arg("engines") = std::vector<std::string>{},
        py::arg("dt") = py::none(), py::arg("duration") = py::none(), py::arg("set") = py::dict(),
        py::arg("options") = py::dict(), py::arg("out") = py::none(),
        py::arg("settings") = "default",
        "Internal: impactbench.compare returns its table as columns or a DataFrame.");
}

}  // namespace impactbench::python
