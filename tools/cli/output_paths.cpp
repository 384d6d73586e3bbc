#include "tools/cli/output_paths.hpp"

#include "lib/output/atomic_file.hpp"
#include "tools/cli/command.hpp"

namespace impactbench::cli {

namespace {

/// The file a path will write to: links followed, ".", ".." and repeated separators resolved.
std::filesystem::path identity_of(const std::filesystem::path& path) {
  std::error_code error;
  const auto resolved = std::filesystem::absolute(output::follow_symlinks(path));
  const auto canonical = std::filesystem::weakly_canonical(resolved, error);
  return error ? resolved.lexically_normal() : canonical;
}

}  // namespace

void check_output_path(const std::filesystem::path& path, const std::string& option) {
  std::filesystem::path target;
  try {
    target = output::follow_symlinks(path);
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

}  // namespace impactbench::cli
