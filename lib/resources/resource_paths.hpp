#pragma once
// Where impactbench finds what it ships besides code: scenario files, plotting scripts, FCLIB
// problems and benchmark binaries. Nothing is looked up in the source tree: every path is
// relative to the running program, so the build tree and an installed prefix work alike.
//
// Layout (the same under a build preset's folder and under an install prefix):
//   bin/impactbench                 the program (tests sit in tests/, one level down, too)
//   libexec/impactbench/*_bench     benchmark binaries run by `impactbench suite`
//   share/impactbench/scenarios     scenario files (IMPACTBENCH_SCENARIOS overrides)
//   share/impactbench/scripts       Python plotting and conversion scripts
//   share/impactbench/fclib         FCLIB problem files
//   share/impactbench/lcp_siconos   Siconos' LCP test problems (plain-text LCP files)
//   share/impactbench/scenarios/data/cube_toss/tosses   recorded cube tosses (validate)
#include <filesystem>

namespace impactbench::resources {

/// The folder of the running program (from /proc/self/exe), or the one set below.
std::filesystem::path executable_directory();

/// Makes `directory` stand for the running program's folder: the Python module, whose process
/// is the interpreter, names PREFIX/bin of the prefix it was built or installed in.
void set_program_directory(const std::filesystem::path& directory);

/// share/impactbench beside the running program (one or two levels up), else the install
/// prefix's; throws std::runtime_error naming the places tried when none exists.
std::filesystem::path data_directory();

/// IMPACTBENCH_SCENARIOS when set and not empty, else data_directory()/scenarios.
std::filesystem::path scenario_directory();

/// data_directory()/scripts.
std::filesystem::path scripts_directory();

/// data_directory()/scenarios/data/cube_toss/tosses: the shipped recorded tosses (not below
/// IMPACTBENCH_SCENARIOS, which names scenario files only).
std::filesystem::path cube_toss_directory();

/// data_directory()/fclib.
std::filesystem::path fclib_directory();

/// data_directory()/lcp_siconos.
std::filesystem::path lcp_collection_directory();

/// libexec/impactbench beside the running program; empty when there is none (the suite then
/// reports its benchmarks as skipped).
std::filesystem::path benchmark_directory();

/// The Python interpreter for the scripts: Debian's /usr/bin/python3 when present (a pyenv
/// python3 first on PATH cannot see Debian's matplotlib), else python3 from PATH; the
/// environment variable IMPACTBENCH_PYTHON names another.
std::filesystem::path python_interpreter();

}  // namespace impactbench::resources
