#include "lib/scenario/scenario_error.hpp"

#include <utility>

namespace impactbench::scenario {

namespace {
std::string format_message(const std::string& path, int line, const std::string& field,
                           const std::string& problem) {
  std::string message;
  message.reserve(path.size() + field.size() + problem.size() + 16);
  message.append(path);
  if (line > 0) message.append(":").append(std::to_string(line));
  message.append(": ");
  if (!field.empty()) message.append(field).append(": ");
  return message.append(problem);
}
}  // namespace

ScenarioError::ScenarioError(std::string path, int line, std::string field, std::string problem)
    : std::runtime_error(format_message(path, line, field, problem)),
      path_(std::move(path)),
      line_(line),
      field_(std::move(field)),
      problem_(std::move(problem)) {}

}  // namespace impactbench::scenario
