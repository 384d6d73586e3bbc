#pragma once
// The number and text formats shared by the CSV writers: numbers as output::number_chars (the
// shortest text that round-trips every double exactly), text fields quoted as RFC 4180 asks
// when they hold , " or newlines.
#include <ostream>
#include <string>

namespace impactbench::output {

void write_number(std::ostream& out, double value);
/// Appends the number's text to `line` (a row being built before it is written at once).
void append_number(std::string& line, double value);
void write_text(std::ostream& out, const std::string& text);

}  // namespace impactbench::output
