#pragma once
// The points of a sweep: every scenario × engine × the grid axes that engine uses (dt only for
// engines with a step, tolerance and solver only for engines that have one, settings only for
// engines with a set besides the default, an option axis only for its engine), each with a stable
// id (a hash of its definition) and checked before any point runs.
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tools/cli/sweep_spec.hpp"

namespace impactbench::cli {

/// More points than this are refused unless the sweep is forced (--force).
inline constexpr std::size_t kMaxPointsUnforced = 100000;

struct SweepPoint {
  std::size_t index = 0;  ///< position in the expansion (the order of the file)
  std::string id;         ///< 16 hex digits of the hash of definition()
  std::string scenario;
  std::string engine;
  std::optional<std::string> dt, tolerance, solver;
  std::optional<std::string> settings_set;  ///< unset: the engine has no set the axis names
  std::vector<std::pair<std::string, std::string>> sets;     ///< name, value
  std::vector<std::pair<std::string, std::string>> options;  ///< key (no engine), value
  /// "scenario=...; engine=...; dt=...; settings=expert; set.name=...; option.key=..."
  /// (canonical; `settings=default` is left out: that point is the one of no settings axis).
  std::string definition() const;
};

/// The number of points the spec expands to (without building them).
double count_points(const SweepSpec& spec);

/// Expands the spec; throws ScenarioError for more than kMaxPointsUnforced points unless
/// `force`, for an unknown engine, and for an axis no engine swept can use.
std::vector<SweepPoint> expand_points(const SweepSpec& spec, bool force);

/// "set.name=value; option.key=value" of the point, for the merged CSV.
std::string joined(const std::vector<std::pair<std::string, std::string>>& entries,
                   const std::string& prefix);

}  // namespace impactbench::cli
