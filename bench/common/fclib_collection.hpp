#pragma once
// The FCLIB problem files of a folder (share/impactbench/fclib for the benchmarks), listed in name
// order and loaded once (global problems reduced to the local form outside any timing).
#include <filesystem>
#include <string>
#include <vector>

#include "solvers/io/fclib_file.hpp"

namespace impactbench::bench {

/// The files of `folder` whose extension is `extension` (with its dot), sorted by name.
std::vector<std::filesystem::path> collection_files(const std::filesystem::path& folder,
                                                    const std::string& extension);

/// The *.hdf5 files of `folder`, sorted by name.
std::vector<std::filesystem::path> fclib_collection_files(const std::filesystem::path& folder);

/// read_fclib_file(path), cached for the lifetime of the process.
const solvers::FclibProblem& cached_fclib_problem(const std::filesystem::path& path);

}  // namespace impactbench::bench
