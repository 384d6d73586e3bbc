#include "lib/output/run_outputs.hpp"

namespace impactbench::output {

RunOutputs::RunOutputs(const std::filesystem::path& trajectory_path,
                       const std::optional<std::filesystem::path>& events_path)
    : trajectory_(trajectory_path) {
  if (events_path) events_.emplace(*events_path);
}

void RunOutputs::write_header(const Trajectory& names) {
  if (!trajectory_.has_header())
    trajectory_.write_header(names.position_names, names.velocity_names);
}

void RunOutputs::write_sample(const Trajectory& names, const TrajectorySample& sample) {
  write_header(names);
  trajectory_.write_row(sample);
}

void RunOutputs::commit(const std::vector<EventRecord>& events) {
  if (events_)
    for (const auto& event : events) events_->write_row(event);
  // Together: a failure of either (a full device, an unwritable target) leaves neither.
  if (events_)
    commit_together({&trajectory_.file(), &events_->file()});
  else
    trajectory_.commit();
}

void write_run_outputs(const Trajectory& trajectory, const std::vector<EventRecord>& events,
                       const std::filesystem::path& trajectory_path,
                       const std::optional<std::filesystem::path>& events_path) {
  RunOutputs outputs(trajectory_path, events_path);
  outputs.write_header(trajectory);
  for (const auto& sample : trajectory.samples) outputs.write_sample(trajectory, sample);
  outputs.commit(events);
}

}  // namespace impactbench::output
