#include "lib/output/events_csv.hpp"

#include "lib/output/csv_format.hpp"

namespace impactbench::output {

EventsCsvWriter::EventsCsvWriter(const std::filesystem::path& path) : file_(path) {
  file_.stream() << "t,contact,kind,from_mode,to_mode,impulse_n,impulse_t\n";
}

void EventsCsvWriter::write_row(const EventRecord& event) {
  auto& out = file_.stream();
  write_number(out, event.t);
  for (const auto* text : {&event.contact, &event.kind, &event.from_mode, &event.to_mode}) {
    out << ',';
    write_text(out, *text);
  }
  out << ',';
  write_number(out, event.impulse_n);
  out << ',';
  write_number(out, event.impulse_t);
  out << '\n';
}

void write_events_csv(const std::filesystem::path& path, const std::vector<EventRecord>& events) {
  EventsCsvWriter writer(path);
  for (const auto& event : events) writer.write_row(event);
  writer.commit();
}

}  // namespace impactbench::output
