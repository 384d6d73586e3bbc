#include "lib/output/run_outputs.hpp"

#include "lib/output/events_csv.hpp"
#include "lib/output/trajectory_csv.hpp"

namespace impactbench::output {

void write_run_outputs(const Trajectory& trajectory, const std::vector<EventRecord>& events,
                       const std::filesystem::path& trajectory_path,
                       const std::optional<std::filesystem::path>& events_path) {
  TrajectoryCsvWriter trajectory_writer(trajectory_path, trajectory.position_names,
                                        trajectory.velocity_names);
  for (const auto& sample : trajectory.samples) trajectory_writer.write_row(sample);
  std::optional<EventsCsvWriter> events_writer;
  if (events_path) {
    events_writer.emplace(*events_path);
    for (const auto& event : events) events_writer->write_row(event);
  }
  trajectory_writer.commit();
  if (events_writer) events_writer->commit();
}

}  // namespace impactbench::output
