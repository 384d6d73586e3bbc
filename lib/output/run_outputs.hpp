#pragma once
// Writes the files of one run: the trajectory CSV and, if asked, the events CSV. Both are
// prepared before either is committed, so a failure in either leaves neither file.
#include <filesystem>
#include <optional>
#include <vector>

#include "lib/output/trajectory.hpp"

namespace impactbench::output {

void write_run_outputs(const Trajectory& trajectory, const std::vector<EventRecord>& events,
                       const std::filesystem::path& trajectory_path,
                       const std::optional<std::filesystem::path>& events_path);

}  // namespace impactbench::output
