#pragma once
// Checks on the files a command will write, made before any work starts: the directory exists,
// the path is not a directory, and no two outputs name the same file in different spellings
// (o/t.csv and o/./t.csv, or a symbolic link and its target).
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace impactbench::cli {

/// Throws CliError (exit 1) when `path`, given as `option`, cannot be written.
void check_output_path(const std::filesystem::path& path, const std::string& option);

/// Throws CliError (exit 2) when two of the (option, path) pairs name the same file.
void check_distinct_outputs(
    const std::vector<std::pair<std::string, std::filesystem::path>>& outputs);

/// Throws CliError (exit 2) when an output names one of the (option, path) inputs: writing it
/// would destroy what the command reads.
void check_outputs_spare_inputs(
    const std::vector<std::pair<std::string, std::filesystem::path>>& outputs,
    const std::vector<std::pair<std::string, std::filesystem::path>>& inputs);

}  // namespace impactbench::cli
