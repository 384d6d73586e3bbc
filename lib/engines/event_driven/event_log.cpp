#include "lib/engines/event_driven/event_log.hpp"

#include <iomanip>

namespace impactbench::engines::event_driven {
namespace {

// RFC 4180: a field with a comma, quote or newline is quoted, quotes doubled.
void write_field(std::ostream& out, const std::string& field) {
  if (field.find_first_of(",\"\n") == std::string::npos) {
    out << field;
    return;
  }
  out << '"';
  for (char c : field) out << (c == '"' ? "\"\"" : std::string(1, c));
  out << '"';
}

}  // namespace

void write_events_csv(std::ostream& out, const std::vector<Event>& events) {
  const auto precision = out.precision(17);
  out << "t,contact,kind,from_mode,to_mode,impulse_n,impulse_t\n";
  for (const auto& e : events) {
    out << e.t << ',';
    write_field(out, e.contact);
    out << ',' << to_string(e.kind) << ',' << to_string(e.from_mode) << ',' << to_string(e.to_mode)
        << ',' << e.impulse_n << ',' << e.impulse_t_scalar() << '\n';
  }
  out.precision(precision);
}

void write_summary(std::ostream& out, const EventDrivenResult& result) {
  out << "status: " << to_string(result.status);
  if (!result.message.empty()) out << " (" << result.message << ')';
  out << '\n' << result.summary.to_text();
  out << "integrator steps: " << result.summary.steps
      << ", rhs evaluations: " << result.summary.rhs_evaluations
      << ", root function evaluations: " << result.summary.root_evaluations
      << ", segments: " << result.summary.segments << '\n';
}

}  // namespace impactbench::engines::event_driven
