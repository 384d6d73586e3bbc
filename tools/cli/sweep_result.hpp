#pragma once
// One sweep point's result file, DIR/points/<id>.result: written atomically, sealed by a
// checksum of its lines, carrying the hash of what determined it (sweep_prepared_point.hpp).
//
//   impactbench-sweep-result 1
//   id <id>
//   hash <hash>
//   status ok|failed|timeout
//   reason <text>
//   reference <text>
//   cpu_seconds <number>
//   metric <name> <number>      (one line per metric, in the column order of metrics.csv)
//   end <checksum of the lines above>
#include <filesystem>
#include <optional>
#include <string>

#include "tools/compare/analytic_errors.hpp"

namespace impactbench::cli {

struct PointResult {
  std::string id;
  std::string hash;
  std::string status;  ///< ok, failed or timeout
  std::string reason;  ///< why it failed or timed out, else empty
  std::string reference;
  double cpu_seconds = 0;  ///< process CPU time of the engine's stepping
  compare::NamedValues metrics;
};

std::filesystem::path result_path(const std::filesystem::path& dir, const std::string& id);

/// Writes the result atomically (a killed writer leaves no file); throws std::runtime_error.
void write_point_result(const std::filesystem::path& dir, const PointResult& result);

/// The result in `path`; nullopt (with `problem` set) when the file is missing, truncated,
/// corrupted (its checksum differs) or does not parse.
std::optional<PointResult> read_point_result(const std::filesystem::path& path,
                                             std::string& problem);

}  // namespace impactbench::cli
