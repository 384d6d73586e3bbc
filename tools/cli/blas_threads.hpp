#pragma once
// A build with the Siconos engine links OpenBLAS, whose worker threads start with the process and
// spin after every call: their CPU time would be counted in the process CPU time of every run
// (measured: 0.1 s during a 0.2 s sleep). None of the engines uses them, so such a build runs
// itself again with OPENBLAS_NUM_THREADS=1 before doing anything else.
namespace impactbench::cli {

/// Without the Siconos engine: nothing. With it and OPENBLAS_NUM_THREADS unset or not 1: sets it
/// to 1 and replaces the process with itself (argv unchanged); returns only if that fails.
void restart_with_one_blas_thread(char** argv);

}  // namespace impactbench::cli
