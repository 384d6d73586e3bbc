#include "lib/validation/toss_csv.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <vector>

#include "lib/output/message_text.hpp"
#include "lib/output/number_text.hpp"

namespace impactbench::validation {
namespace {

constexpr std::array<const char*, 14> kColumns = {"t",  "x",  "y",  "z",  "qw", "qx", "qy",
                                                  "qz", "vx", "vy", "vz", "wx", "wy", "wz"};

[[noreturn]] void fail(const std::filesystem::path& path, long line, const std::string& what) {
  throw TossDataError(output::printable(path.string()) + ":" + std::to_string(line) + ": " + what);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

std::string trimmed(std::string s) {
  while (!s.empty() && (s.back() == '\r' || s.back() == ' ')) s.pop_back();
  std::size_t start = 0;
  while (start < s.size() && s[start] == ' ') ++start;
  return s.substr(start);
}

/// The first byte no CSV text line holds (a control byte; in the header, any non-ASCII byte),
/// described; empty when there is none.
std::string unprintable_byte(const std::string& line, bool header) {
  for (const char c : line) {
    const auto byte = static_cast<unsigned char>(c);
    if ((byte < 0x20 && c != '\t' && c != '\r') || byte == 0x7f || (header && byte >= 0x80)) {
      char text[8];
      std::snprintf(text, sizeof text, "0x%02x", byte);
      return std::string("byte ") + text;
    }
  }
  return {};
}

}  // namespace

Toss read_toss(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, 0, "cannot open the file");
  Toss toss;
  toss.name = path.stem().string();
  std::string text;
  long line_number = 0;
  std::array<int, kColumns.size()> index{};
  std::size_t field_count = 0;
  while (std::getline(in, text)) {
    ++line_number;
    if (const std::string bad = unprintable_byte(text, line_number == 1); !bad.empty())
      fail(path, line_number, "not CSV text (" + bad + ")");
    if (line_number == 1) {
      const auto names = split(text);
      field_count = names.size();
      for (std::size_t c = 0; c < kColumns.size(); ++c) {
        index[c] = -1;
        for (std::size_t k = 0; k < names.size(); ++k)
          if (trimmed(names[k]) == kColumns[c]) index[c] = static_cast<int>(k);
        if (index[c] < 0)
          fail(path, 1,
               std::string("missing column '") + kColumns[c] +
                   "' (a toss file's header names t, x, y, z, qw, qx, qy, qz, vx, vy, vz, wx, "
                   "wy, wz)");
      }
      continue;
    }
    if (trimmed(text).empty()) continue;
    const auto fields = split(text);
    if (fields.size() != field_count)
      fail(path, line_number,
           "not CSV: " + std::to_string(fields.size()) + " fields, the header has " +
               std::to_string(field_count));
    std::array<double, kColumns.size()> x{};
    for (std::size_t c = 0; c < kColumns.size(); ++c) {
      const std::string field = trimmed(fields[static_cast<std::size_t>(index[c])]);
      const char* end = field.data() + field.size();
      const auto [stop, error] = std::from_chars(field.data(), end, x[c]);
      if (error != std::errc() || stop != end || field.empty())
        fail(path, line_number,
             std::string("column ") + kColumns[c] + ": '" + output::printable(field, 40) +
                 "' is not a number");
      if (!std::isfinite(x[c]))
        fail(path, line_number, std::string("column ") + kColumns[c] + " is " + field);
    }
    TossSample s;
    s.t = x[0];
    s.position = {x[1], x[2], x[3]};
    const Eigen::Vector4d wxyz(x[4], x[5], x[6], x[7]);
    if (std::abs(wxyz.norm() - 1.0) > kQuaternionTolerance)
      fail(path, line_number,
           "quaternion (qw, qx, qy, qz) has norm " + output::number_text(wxyz.norm()) +
               ", not 1 within " + output::number_text(kQuaternionTolerance));
    s.orientation = Eigen::Quaterniond(x[4], x[5], x[6], x[7]).normalized();
    s.velocity = {x[8], x[9], x[10]};
    s.angular_velocity_body = {x[11], x[12], x[13]};
    if (!toss.samples.empty() && !(s.t > toss.samples.back().t))
      fail(path, line_number,
           "time " + output::number_text(s.t) + " does not increase (previous " +
               output::number_text(toss.samples.back().t) + ")");
    toss.samples.push_back(s);
  }
  if (line_number == 0) fail(path, 1, "empty file (not a toss CSV)");
  if (toss.samples.size() < 2)
    fail(path, line_number,
         std::to_string(toss.samples.size()) + " sample(s); a toss needs at least 2");
  return toss;
}

}  // namespace impactbench::validation
