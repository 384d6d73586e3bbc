#pragma once
// Writes the files of one run: the trajectory CSV and, if asked, the events CSV. Both are
// prepared before either is committed, so a failure in either (or in the run that streams its
// rows into them) leaves neither file.
#include <filesystem>
#include <optional>
#include <vector>

#include "lib/output/events_csv.hpp"
#include "lib/output/trajectory.hpp"
#include "lib/output/trajectory_csv.hpp"

namespace impactbench::output {

/// The run's files while it runs: trajectory rows arrive one at a time, the events at the end.
class RunOutputs {
 public:
  /// Opens both temporary files, so an output that cannot be written fails before the run.
  RunOutputs(const std::filesystem::path& trajectory_path,
             const std::optional<std::filesystem::path>& events_path);

  /// Writes the header from the names of `names` (its samples unused) unless written already.
  void write_header(const Trajectory& names);
  /// Appends a row; the first one also writes the header.
  void write_sample(const Trajectory& names, const TrajectorySample& sample);
  /// Writes the events, then makes both files appear. Throws std::runtime_error when a file
  /// cannot be completed (then neither is left behind).
  void commit(const std::vector<EventRecord>& events);

 private:
  TrajectoryCsvWriter trajectory_;
  std::optional<EventsCsvWriter> events_;
};

void write_run_outputs(const Trajectory& trajectory, const std::vector<EventRecord>& events,
                       const std::filesystem::path& trajectory_path,
                       const std::optional<std::filesystem::path>& events_path);

}  // namespace impactbench::output
