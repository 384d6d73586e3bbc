#include "tools/cli/output_paths.hpp"

#include "lib/output/atomic_file.hpp"
#include "tools/cli/command.hpp"

namespace impactbench::cli {

namespace {

/// The file a path will write to: links followed, ".", ".." and repeated separators resolved.
std::filesystem::path identity_of(const std::filesystem::path& path) {
  std::error_code error;
  const auto resolved = std::filesystem::absolute(output::output_target(path));
  const auto canonical = std::filesystem::weakly_canonical(resolved, error);
  return error ? resolved.lexically_normal() : canonical;
}

}  // namespace

void check_output_path(const std::filesystem::path& path, const std::string& option) {
  std::filesystem::path target;
  try {
    target = output::output_target(path);
  } catch (const std::exception& error) {
    throw CliError(option + " " + error.what(), kExitFailure);
  }
  std::error_code error;
  const auto directory =
      target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
  if (!std::filesystem::is_directory(directory, error))
    throw CliError(
        option + " " + path.string() + ": directory " + directory.string() + " does not exist",
        kExitFailure);
  if (std::filesystem::is_directory(target, error))
    throw CliError(option + " " + path.string() + " is a directory", kExitFailure);
}

void check_distinct_outputs(
    const std::vector<std::pair<std::string, std::filesystem::path>>& outputs) {
  for (std::size_t i = 0; i < outputs.size(); ++i)
    for (std::size_t j = i + 1; j < outputs.size(); ++j)
      if (identity_of(outputs[i].second) == identity_of(outputs[j].second))
        throw CliError(outputs[i].first + " and " + outputs[j].first + " name the same file (" +
                           outputs[j].second.string() + ")",
                       kExitUsage);
}

void check_outputs_spare_inputs(
    const std::vector<std::pair<std::string, std::filesystem::path>>& outputs,
    const std::vector<std::pair<std::string, std::filesystem::path>>& inputs) {
  for (const auto& [output_option, output] : outputs)
    for (const auto& [input_option, input] : inputs)
      if (identity_of(output) == identity_of(input))
        throw CliError(output_option + " " + output.string() + " names the " + input_option +
                           " file: it would overwrite what the command reads",
                       kExitUsage);
}

}  // namespace impactbench::cli
