#pragma once
// The events CSV of the design: header `t,contact,kind,from_mode,to_mode,impulse_n,impulse_t`,
// one row per event, numbers in the shortest exact form (csv_format.hpp). Written atomically like
// the trajectory CSV.
#include <filesystem>
#include <vector>

#include "lib/output/atomic_file.hpp"
#include "lib/output/trajectory.hpp"

namespace impactbench::output {

class EventsCsvWriter {
 public:
  explicit EventsCsvWriter(const std::filesystem::path& path);
  void write_row(const EventRecord& event);
  void commit() { file_.commit(); }
  AtomicFile& file() { return file_; }

 private:
  AtomicFile file_;
};

void write_events_csv(const std::filesystem::path& path, const std::vector<EventRecord>& events);

}  // namespace impactbench::output
