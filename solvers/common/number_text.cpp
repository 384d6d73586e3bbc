#include "solvers/common/number_text.hpp"

#include <charconv>
#include <cstring>

namespace impactbench::output {

char* number_chars(char* first, double value) {
  char* const end = std::to_chars(first, first + kNumberTextCapacity, value).ptr;
  // to_chars writes "1e-04" and "1e+20"; drop the '+' and the exponent's leading zeros.
  char* e = static_cast<char*>(std::memchr(first, 'e', static_cast<std::size_t>(end - first)));
  if (e == nullptr) return end;
  char* out = e + 1;
  const char* in = e + 1;
  if (*in == '-') *out++ = *in++;
  if (*in == '+') ++in;
  while (in + 1 < end && *in == '0') ++in;  // keeps one digit of an all-zero exponent
  while (in < end) *out++ = *in++;
  return out;
}

std::string number_text(double value) {
  char buffer[kNumberTextCapacity];
  return std::string(buffer, number_chars(buffer, value));
}

}  // namespace impactbench::output
