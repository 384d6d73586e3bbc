#include "lib/resources/resource_paths.hpp"

#include <array>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace impactbench::resources {
namespace {

namespace fs = std::filesystem;

// Folders `relative` below the program's parent and grandparent: the program sits in bin/
// (installed or built), tests/ (built) or libexec/impactbench/ (benchmarks).
std::array<fs::path, 2> beside_program(const fs::path& relative) {
  const fs::path here = executable_directory();
  return {here.parent_path() / relative, here.parent_path().parent_path() / relative};
}

// Set once, when the Python module is imported; empty: the running program's own folder.
fs::path& program_directory_override() {
  static fs::path directory;
  return directory;
}

}  // namespace

void set_program_directory(const fs::path& directory) {
  program_directory_override() = directory;
}

fs::path executable_directory() {
  if (!program_directory_override().empty()) return program_directory_override();
  std::error_code error;
  const fs::path program = fs::read_symlink("/proc/self/exe", error);
  if (error) throw std::runtime_error("cannot locate the running program (/proc/self/exe)");
  return program.parent_path();
}

fs::path data_directory() {
  std::error_code error;
  std::string tried;
  for (const fs::path& candidate : beside_program("share/impactbench")) {
    if (fs::is_directory(candidate, error)) return candidate;
    tried += (tried.empty() ? "" : ", ") + candidate.string();
  }
#ifdef IMPACTBENCH_INSTALL_DATA_DIR
  // A program of a library user, linked against an installed impactbench.
  if (fs::is_directory(IMPACTBENCH_INSTALL_DATA_DIR, error)) return IMPACTBENCH_INSTALL_DATA_DIR;
  tried += std::string(", ") + IMPACTBENCH_INSTALL_DATA_DIR;
#endif
  throw std::runtime_error("impactbench data folder not found (tried " + tried +
                           "); set IMPACTBENCH_SCENARIOS to a scenario folder");
}

fs::path scenario_directory() {
  if (const char* overridden = std::getenv("IMPACTBENCH_SCENARIOS"); overridden && *overridden)
    return overridden;
  return data_directory() / "scenarios";
}

fs::path scripts_directory() {
  return data_directory() / "scripts";
}

fs::path cube_toss_directory() {
  return data_directory() / "scenarios" / "data" / "cube_toss" / "tosses";
}

fs::path fclib_directory() {
  return data_directory() / "fclib";
}

fs::path lcp_collection_directory() {
  return data_directory() / "lcp_siconos";
}

fs::path benchmark_directory() {
  std::error_code error;
  for (const fs::path& candidate : beside_program("libexec/impactbench"))
    if (fs::is_directory(candidate, error)) return candidate;
  return {};
}

fs::path python_interpreter() {
  // Another interpreter (a virtual environment with matplotlib, say) when the user names one.
  if (const char* named = std::getenv("IMPACTBENCH_PYTHON"); named && *named) return named;
  std::error_code error;
  if (fs::exists("/usr/bin/python3", error)) return "/usr/bin/python3";
  return "python3";
}

}  // namespace impactbench::resources
