#pragma once
// A sweep file (docs/sweeps.md): the scenarios, engines and grids of a campaign, read from TOML
// with the line of every value, so that each refusal says `path:line: field: what`.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace impactbench::cli {

/// One value of a grid, as text (numbers in round-trip form), with the line it is on.
struct SpecValue {
  std::string text;
  int line = 0;
};

/// A grid axis: the field's name in the file ("grid.dt", "grid.set.restitution",
/// "grid.option.moreau.theta") and its values.
struct SpecAxis {
  std::string field;
  std::string key;  ///< the parameter or ENGINE.key of set/option axes, else empty
  int line = 0;
  std::vector<SpecValue> values;
};

/// [validate]: each point is `impactbench validate` of its engine over recorded tosses, at its
/// grid.set parameters of cube_toss, instead of a compare run.
struct SpecValidate {
  int line = 0;
  std::string tosses = "train";          ///< --tosses
  std::string initial_state = "sample";  ///< sample | fit
  std::filesystem::path data;            ///< empty: the shipped tosses; else relative to the file
  /// The folder of toss files: `data`, or the shipped tosses' when it is empty.
  std::filesystem::path folder() const;
};

struct SweepSpec {
  std::filesystem::path path;
  std::string text;  ///< the file's content
  std::vector<SpecValue> scenarios;
  std::vector<SpecValue> engines;
  int grid_line = 0;               ///< the line of [grid], for refusals of the whole grid
  std::optional<double> duration;  ///< simulated time of every point; unset: each scenario's
  double time_limit = 0;           ///< seconds of wall time per point; 0: none
  std::optional<SpecAxis> dt, tolerance, solver;
  std::optional<SpecAxis> settings_set;  ///< grid.settings: "default", "expert" (--settings)
  std::vector<SpecAxis> sets;            ///< grid.set.NAME
  std::vector<SpecAxis> options;         ///< grid.option."ENGINE.key"
  std::optional<SpecValidate> validate;  ///< [validate]: validate points, not compare runs
  // [slurm]: the job array's shards, concurrency, time and memory per task (flags override).
  std::size_t slurm_shards = 0;       ///< 0: one per 10 points, at most 1000
  std::size_t slurm_concurrency = 0;  ///< 0: no limit
  std::string slurm_time;             ///< --time of sbatch; empty: the cluster's default
  std::string slurm_mem;              ///< --mem of sbatch; empty: the cluster's default
  std::string slurm_partition;
};

/// Reads a sweep file; throws scenario::ScenarioError (`path:line: field: what`) for a syntax
/// error, an unknown key, a value of the wrong kind or an empty grid. Names of scenarios and
/// engines and the values themselves are checked by check_sweep (sweep_points.hpp).
SweepSpec read_sweep_spec(const std::filesystem::path& path);

}  // namespace impactbench::cli
