#include "common/friction_bench_run.hpp"

#include <algorithm>
#include <ctime>

namespace impactbench::bench {

solvers::SolverOptions friction_bench_options(const std::string& solver) {
  solvers::SolverOptions options;
  options.measure_seconds = false;  // timed here, by process CPU time
  options.tolerance = 1e-8;
  options.max_iterations = solver == "lemke" ? 100000 : (solver == "nsn" ? 200 : 2000);
  return options;
}

void run_friction_solve(benchmark::State& state, const solvers::FrictionProblem& problem,
                        const std::string& solver) {
  const solvers::SolverOptions options = friction_bench_options(solver);
  solvers::SolverResult result;
  double cpu_seconds = 0.0;
  for (auto _ : state) {
    // CPU time, not wall time: the benchmark machine is shared and wall time includes waiting.
    const std::clock_t start = std::clock();
    result = solvers::solve_friction(problem, solver, options);
    cpu_seconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    benchmark::DoNotOptimize(result.solution.data());
  }
  state.counters["solver_iterations"] = result.iterations;
  state.counters["residual"] = result.residual;
  state.counters["converged"] = result.converged() ? 1.0 : 0.0;
  state.counters["contacts"] = problem.num_contacts();
  state.counters["seconds_per_sweep"] = cpu_seconds / std::max(1, result.iterations);
  state.counters["solve_seconds"] = cpu_seconds;
  state.SetLabel(std::string(solvers::to_string(result.status)));
}

}  // namespace impactbench::bench
