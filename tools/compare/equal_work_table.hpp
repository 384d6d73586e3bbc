#pragma once
// The suite's "piles at equal work" table: the piles stepped by Moreau–Jean, Box2D and Bullet
// under the equal-work settings (tools/engines/registry/equal_work.hpp), each engine's CPU time
// per step and Moreau–Jean's time over it, beside the physical-accuracy criteria of the same
// run (penetration, Signorini, complementarity, friction cone, energy rise), so that speed is
// never shown without accuracy.
#include <filesystem>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "lib/scenario/scenario.hpp"
#include "tools/compare/compare.hpp"

namespace impactbench::compare {

struct EqualWorkCase {
  std::string label;      ///< e.g. "disk_pile, 1,000 disks"
  std::string directory;  ///< where its compare files go, under the suite's equal_work/
  std::string scenario;   ///< shipped scenario name
  scenario::ParameterOverrides overrides;
};

/// N = 1,000 and 10,000 disks (the latter in a 100 m wide box) and 1,000 spheres; `quick`: the
/// 1,000-disk pile alone.
std::vector<EqualWorkCase> equal_work_cases(bool quick);

struct BareTiming {
  double ms_per_step = std::numeric_limits<double>::quiet_NaN();  ///< [ms]
  std::string failure;  ///< why the bare loop failed, or empty
};

struct EqualWorkOutcome {
  EqualWorkCase scene;
  CompareReport report;  ///< one row per engine, Moreau–Jean first
  std::string failure;   ///< why the comparison did not run, or empty
  /// Engine → its CPU time per step in a bare loop (a timing-only run, nothing of ours between
  /// its steps).
  std::map<std::string, BareTiming> bare;
};

/// Runs one case for 1 s of simulated time through `compare` (its files go to `out`), then
/// each engine that ran again as a bare loop (RecordingOptions::timing_only) with the same
/// settings, for its time per step: our recording between the steps of the compared run
/// evicts the engine's data from the caches and inflated Box2D's step time by a third or more.
EqualWorkOutcome run_equal_work(const EqualWorkCase& scene, const std::filesystem::path& out);

/// The table: one row per scene and engine. Writes the same as CSV to `csv`.
std::string equal_work_markdown(const std::vector<EqualWorkOutcome>& outcomes);
void write_equal_work_csv(const std::filesystem::path& csv,
                          const std::vector<EqualWorkOutcome>& outcomes);

}  // namespace impactbench::compare
