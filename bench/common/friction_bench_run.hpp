#pragma once
// One friction solve inside a Google Benchmark loop with the counters every friction benchmark
// reports: solver_iterations (not "iterations", Google Benchmark's own column), residual,
// converged, contacts, CPU seconds of the solve and per sweep (or per pivot).
#include <string>

#include <benchmark/benchmark.h>

#include "solvers/friction/friction_solvers.hpp"

namespace impactbench::bench {

/// Options of the friction benchmarks: FCLIB-style tolerance 1e-8 and a bounded budget.
solvers::SolverOptions friction_bench_options(const std::string& solver);

void run_friction_solve(benchmark::State& state, const solvers::FrictionProblem& problem,
                        const std::string& solver);

}  // namespace impactbench::bench
