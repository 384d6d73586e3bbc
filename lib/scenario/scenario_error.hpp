#pragma once
// The one exception type of scenario loading. Its message always reads
//     <path>:<line>: <field>: <what is wrong>
// (the ":<line>" part is left out when the error has no place in the file, e.g. a bad --set),
// so that a user can jump straight to the offending line.
#include <stdexcept>
#include <string>

namespace impactbench::scenario {

class ScenarioError : public std::runtime_error {
 public:
  /// `line` is 1-based; 0 means "no line" (errors from command-line overrides).
  ScenarioError(std::string path, int line, std::string field, std::string problem);

  const std::string& path() const { return path_; }
  int line() const { return line_; }
  const std::string& field() const { return field_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string path_;
  int line_;
  std::string field_;
  std::string problem_;
};

}  // namespace impactbench::scenario
