#include "lib/engines/settings/setting_fields.hpp"

#include <cmath>
#include <cstdlib>
#include <limits>

namespace impactbench::engines {
namespace {

// Values in messages are cut so that a pasted file cannot flood the terminal.
std::string quoted(const std::string& text) {
  constexpr std::size_t kLongest = 40;
  std::string shown = text.size() > kLongest ? text.substr(0, kLongest) + "..." : text;
  for (char& c : shown)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  return "'" + shown + "'";
}

double finite_number(const std::string& text) {
  char* end = nullptr;
  const double x = text.empty() ? 0.0 : std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(x))
    throw std::invalid_argument("must be a finite number, got " + quoted(text));
  return x;
}

}  // namespace

std::string to_string(SettingSource source) {
  switch (source) {
    case SettingSource::kDefault:
      return "default";
    case SettingSource::kExpert:
      return "expert";
    case SettingSource::kScenario:
      return "scenario";
    case SettingSource::kCommandLine:
      return "command line";
    case SettingSource::kBuiltIn:
      return "built in";
    case SettingSource::kReferenceSampling:
      return "reference sampling";
  }
  return "?";
}

bool NumberRange::contains(double x) const {
  const bool above = low_open ? x > low : x >= low;
  const bool below = std::isinf(high) ? x < high : (high_open ? x < high : x <= high);
  return above && below;
}

std::string NumberRange::text() const {
  if (std::isinf(high)) return (low_open ? "> " : ">= ") + output::number_text(low);
  return std::string("in ") + (low_open ? "(" : "[") + output::number_text(low) + ", " +
         output::number_text(high) + (high_open ? ")" : "]");
}

double parse_number(const std::string& text, const NumberRange& range) {
  const double x = finite_number(text);
  if (!range.contains(x))
    throw std::invalid_argument("must be " + range.text() + ", got " + quoted(text));
  return x;
}

int parse_whole(const std::string& text, int low, int high) {
  const double x = finite_number(text);
  if (x < low || x > high)
    throw std::invalid_argument("must be a whole number in [" + std::to_string(low) + ", " +
                                std::to_string(high) + "], got " + quoted(text));
  if (x != std::floor(x))
    throw std::invalid_argument("must be a whole number, got " + quoted(text));
  return static_cast<int>(x);
}

bool parse_switch(const std::string& text) {
  if (text == "1" || text == "true") return true;
  if (text == "0" || text == "false") return false;
  throw std::invalid_argument("must be 0/1 or true/false, got " + quoted(text));
}

std::string switch_text(bool value) {
  return value ? "true" : "false";
}

std::string parse_name(const std::string& text, const std::vector<std::string>& names) {
  for (const std::string& name : names)
    if (name == text) return text;
  throw std::invalid_argument("must be one of " + join_names(names) + ", got " + quoted(text));
}

std::string join_names(const std::vector<std::string>& names, const std::string& last) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += i + 1 == names.size() ? " " + last + " " : ", ";
    out += names[i];
  }
  return out;
}

}  // namespace impactbench::engines
