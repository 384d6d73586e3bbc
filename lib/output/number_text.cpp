#include "lib/output/number_text.hpp"

#include <charconv>

namespace impactbench::output {

std::string number_text(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  std::string text(buffer, result.ptr);
  // to_chars writes "1e-04" and "1e+20"; drop the '+' and the exponent's leading zeros.
  const auto e = text.find('e');
  if (e == std::string::npos) return text;
  std::string exponent = text.substr(e + 1);
  const bool negative = !exponent.empty() && exponent.front() == '-';
  if (!exponent.empty() && (exponent.front() == '-' || exponent.front() == '+'))
    exponent.erase(0, 1);
  const auto digits = exponent.find_first_not_of('0');
  exponent = digits == std::string::npos ? "0" : exponent.substr(digits);
  return text.substr(0, e + 1) + (negative ? "-" : "") + exponent;
}

}  // namespace impactbench::output
