#include "lib/output/csv_format.hpp"

#include <cstdio>

namespace impactbench::output {

void write_number(std::ostream& out, double value) {
  char text[32];
  const int length = std::snprintf(text, sizeof text, "%.17g", value);
  out.write(text, length);
}

void write_text(std::ostream& out, const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) {
    out << text;
    return;
  }
  out << '"';
  for (const char c : text) {
    if (c == '"') out << '"';
    out << c;
  }
  out << '"';
}

}  // namespace impactbench::output
