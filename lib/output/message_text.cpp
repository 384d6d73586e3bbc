#include "lib/output/message_text.hpp"

#include <cstdio>

namespace impactbench::output {

std::string printable(std::string_view text, std::size_t max_length) {
  std::string escaped;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n') {
      escaped += "\\n";
    } else if (c == '\t') {
      escaped += "\\t";
    } else if (c == '\r') {
      escaped += "\\r";
    } else if (byte < 0x20 || byte == 0x7f) {
      char code[8];
      std::snprintf(code, sizeof code, "\\x%02x", byte);
      escaped += code;
    } else {
      escaped += c;
    }
  }
  if (escaped.size() <= max_length || max_length < 8) return escaped;
  // Keep both ends: the start names the value, the end often holds the offending part.
  const std::size_t head = (max_length - 3) * 2 / 3, tail = max_length - 3 - head;
  return escaped.substr(0, head) + "..." + escaped.substr(escaped.size() - tail);
}

}  // namespace impactbench::output
