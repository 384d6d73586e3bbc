#pragma once
// The hash that names a sweep point and seals its result: 64-bit FNV-1a as 16 hex digits (a
// check that a file is the one expected, not a defence against forgery).
#include <cstdint>
#include <string>
#include <string_view>

namespace impactbench::cli {

inline std::string hash_text(std::string_view text) {
  std::uint64_t hash = 14695981039346656037ull;
  for (const char c : text) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 1099511628211ull;
  }
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string out(16, '0');
  for (int i = 15; i >= 0; --i, hash >>= 4) out[static_cast<std::size_t>(i)] = kDigits[hash & 15];
  return out;
}

}  // namespace impactbench::cli
