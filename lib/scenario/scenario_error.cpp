#include "lib/scenario/scenario_error.hpp"

#include <utility>

#include "lib/output/message_text.hpp"

namespace impactbench::scenario {

namespace {
std::string format_message(const std::string& path, int line, const std::string& field,
                           const std::string& problem) {
  std::string message;
  message.reserve(path.size() + field.size() + problem.size() + 16);
  message.append(output::printable(path, 200));
  if (line > 0) message.append(":").append(std::to_string(line));
  message.append(": ");
  // Fields and problems quote the file's text: keep the message on one readable line.
  if (!field.empty()) message.append(output::printable(field, 120)).append(": ");
  return message.append(output::printable(problem, 400));
}
}  // namespace

ScenarioError::ScenarioError(std::string path, int line, std::string field, std::string problem)
    : std::runtime_error(format_message(path, line, field, problem)),
      path_(std::move(path)),
      line_(line),
      field_(std::move(field)),
      problem_(std::move(problem)) {}

}  // namespace impactbench::scenario
