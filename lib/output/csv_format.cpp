#include "lib/output/csv_format.hpp"

#include "lib/output/number_text.hpp"

namespace impactbench::output {

void write_number(std::ostream& out, double value) {
  char text[kNumberTextCapacity];
  out.write(text, number_chars(text, value) - text);
}

void append_number(std::string& line, double value) {
  char text[kNumberTextCapacity];
  line.append(text, number_chars(text, value));
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
