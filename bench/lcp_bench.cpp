// LCP solvers on reproducible problem families. Names follow lcp/<solver>/<problem>/<n>, so
// e.g. --benchmark_filter='lcp/pgs/.*' selects one solver and '.*/contact_sparse/.*' one family.
// The benchmark time is the time of one solve (problem generation is outside the timed loop).
// Counters: solver_iterations (pivots, sweeps, Newton steps or bases; named so as not to clash
// with Google Benchmark's own "iterations" column), residual ‖min(z, Mz+q)‖∞,
// converged (1/0), contacts (= n), seconds_per_iteration (CPU time of a solve / its iterations).
//
// Families and options: common/lcp_bench_families.hpp.
// Sizes are limited where a method is too slow to keep the default run under two minutes:
// dense problems stop at n = 1000 (Lemke is O(n³) there), enumeration at n = 12.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "common/lcp_bench_families.hpp"
#include "solvers/lcp/lcp_solvers.hpp"

namespace {

using impactbench::solvers::LcpProblem;
using impactbench::solvers::SolverOptions;
using impactbench::solvers::SolverResult;

void run_solver(benchmark::State& state, const std::string& solver, const std::string& family,
                int n) {
  const LcpProblem& p = impactbench::bench::lcp_family_problem(family, n);
  const SolverOptions options = impactbench::bench::lcp_bench_options(solver, family, n);
  SolverResult result;
  for (auto _ : state) {
    result = impactbench::solvers::solve_lcp(p, solver, options);
    benchmark::DoNotOptimize(result.solution.data());
  }
  state.counters["solver_iterations"] = result.iterations;
  state.counters["residual"] = result.residual;
  state.counters["converged"] = result.converged() ? 1 : 0;
  state.counters["contacts"] = n;
  // CPU seconds per solver iteration, averaged over all timed solves: (cpu time) / (solves ×
  // solver iterations). Cross-size ratios of this give the growth exponent per sweep or pivot.
  state.counters["seconds_per_iteration"] = benchmark::Counter(
      std::max(1, result.iterations),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.SetLabel(std::string(to_string(result.status)));
}

struct Plan {
  std::string solver;
  std::string family;
  std::vector<int> sizes;
};

void register_all() {
  const std::vector<Plan> plans = {
      {"lemke", "spd_dense", {10, 100, 1000}},
      {"newton-fb", "spd_dense", {10, 100, 1000}},
      {"pgs", "spd_dense", {10, 100, 1000}},
      {"psor", "spd_dense", {10, 100, 1000}},
      {"enum", "spd_dense", {10, 12}},
      {"lemke", "pmatrix_dense", {10, 100, 1000}},
      {"newton-fb", "pmatrix_dense", {10, 100, 1000}},
      {"lemke", "contact_sparse", {100, 1000}},
      {"newton-fb", "contact_sparse", {100, 1000, 10000}},
      {"pgs", "contact_sparse", {100, 1000, 10000}},
      {"psor", "contact_sparse", {100, 1000, 10000}},
      {"pgs", "contact_sparse_shuffled", {100, 1000, 10000}},
      {"lemke", "murty", {4, 8, 12, 16}},
      {"lemke", "murty_reversed", {4, 6, 8, 10, 12, 14, 16}},
      {"enum", "murty_reversed", {4, 8, 12}},
      {"newton-fb", "murty_reversed", {4, 8, 12, 16}},
  };
  for (const Plan& plan : plans) {
    for (int n : plan.sizes) {
      const std::string name = "lcp/" + plan.solver + "/" + plan.family + "/" + std::to_string(n);
      benchmark::RegisterBenchmark(name.c_str(), [solver = plan.solver, family = plan.family,
                                                  n](benchmark::State& state) {
        run_solver(state, solver, family, n);
      })->Unit(benchmark::kMillisecond);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  // A shorter default minimum time keeps the full run under two minutes; MinTime() per
  // benchmark would append "/min_time:…" to the names. An explicit flag still wins.
  std::vector<char*> args(argv, argv + argc);
  std::string min_time = "--benchmark_min_time=0.1";
  if (std::none_of(args.begin(), args.end(), [](const char* a) {
        return std::string_view(a).starts_with("--benchmark_min_time");
      })) {
    args.insert(args.begin() + 1, min_time.data());
  }
  int count = static_cast<int>(args.size());
  benchmark::Initialize(&count, args.data());
  if (benchmark::ReportUnrecognizedArguments(count, args.data())) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
