#pragma once
// A contact's name "<a>-<b>" from the names of its two sides (bodies, lines, planes), written
// in one pass into the caller's string, whose storage it keeps: the systems name every contact
// they find at every search.
#include <cstring>
#include <string>

namespace impactbench::model {

inline void write_pair_name(const std::string& a, const std::string& b, std::string& name) {
  name.resize(a.size() + 1 + b.size());
  char* out = name.data();
  std::memcpy(out, a.data(), a.size());
  out[a.size()] = '-';
  std::memcpy(out + a.size() + 1, b.data(), b.size());
}

}  // namespace impactbench::model
