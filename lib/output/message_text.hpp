#pragma once
// Text that ends up in a one-line error message: numbers in the shortest form that reads back
// exactly (never 0.000000), and values quoted from files or the command line made printable —
// control characters escaped, so a message stays on one line, and long values cut.
#include <string>
#include <string_view>

#include "lib/output/number_text.hpp"  // numbers in messages

namespace impactbench::output {

/// `text` with control characters escaped as \n, \t, \r or \xNN and, when longer than
/// `max_length` characters, its middle replaced by "...".
std::string printable(std::string_view text, std::size_t max_length = 200);

}  // namespace impactbench::output
