#include "tools/cli/sweep_result.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "lib/output/atomic_file.hpp"
#include "lib/output/number_text.hpp"
#include "tools/cli/sweep_hash.hpp"

namespace impactbench::cli {
namespace {

constexpr const char* kMagic = "impactbench-sweep-result 1";

/// One line of text: newlines and tabs of a reason become spaces.
std::string one_line(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
  return text;
}

/// The whole text as a number (number_text's nan and inf too).
bool parse_number(const std::string& text, double& value) {
  if (text.empty()) return false;
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size();
}

}  // namespace

std::filesystem::path result_path(const std::filesystem::path& dir, const std::string& id) {
  return dir / "points" / (id + ".result");
}

void write_point_result(const std::filesystem::path& dir, const PointResult& result) {
  std::string body = std::string(kMagic) + "\n";
  body += "id " + result.id + "\n";
  body += "hash " + result.hash + "\n";
  body += "status " + result.status + "\n";
  body += "reason " + one_line(result.reason) + "\n";
  body += "reference " + one_line(result.reference) + "\n";
  body += "cpu_seconds " + output::number_text(result.cpu_seconds) + "\n";
  for (const auto& [name, value] : result.metrics)
    body += "metric " + name + " " + output::number_text(value) + "\n";
  std::filesystem::create_directories(dir / "points");
  output::AtomicFile file(result_path(dir, result.id));
  file.stream() << body << "end " << hash_text(body) << "\n";
  file.commit();
}

std::optional<PointResult> read_point_result(const std::filesystem::path& path,
                                             std::string& problem) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    problem = "missing";
    return std::nullopt;
  }
  std::ostringstream all;
  all << in.rdbuf();
  const std::string text = all.str();
  const auto end_at = text.rfind("end ");
  if (end_at == std::string::npos || (end_at > 0 && text[end_at - 1] != '\n') ||
      text.back() != '\n') {
    problem = "truncated (no end line)";
    return std::nullopt;
  }
  const std::string body = text.substr(0, end_at);
  if (text.substr(end_at) != "end " + hash_text(body) + "\n") {
    problem = "corrupted (its checksum differs)";
    return std::nullopt;
  }
  PointResult result;
  std::istringstream lines(body);
  std::string line;
  std::getline(lines, line);
  if (line != kMagic) {
    problem = "not a sweep result";
    return std::nullopt;
  }
  while (std::getline(lines, line)) {
    const auto space = line.find(' ');
    const std::string key = line.substr(0, space);
    const std::string value = space == std::string::npos ? "" : line.substr(space + 1);
    if (key == "id")
      result.id = value;
    else if (key == "hash")
      result.hash = value;
    else if (key == "status")
      result.status = value;
    else if (key == "reason")
      result.reason = value;
    else if (key == "reference")
      result.reference = value;
    else if (key == "cpu_seconds" && parse_number(value, result.cpu_seconds))
      continue;
    else if (key == "metric") {
      const auto name_end = value.find(' ');
      double number = 0;
      if (name_end == std::string::npos || !parse_number(value.substr(name_end + 1), number)) {
        problem = "unreadable metric line '" + line + "'";
        return std::nullopt;
      }
      result.metrics.emplace_back(value.substr(0, name_end), number);
    } else {
      problem = "unreadable line '" + line + "'";
      return std::nullopt;
    }
  }
  if (result.status != "ok" && result.status != "failed" && result.status != "timeout") {
    problem = "unknown status '" + result.status + "'";
    return std::nullopt;
  }
  return result;
}

}  // namespace impactbench::cli
