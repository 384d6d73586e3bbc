// LCP solvers on reproducible problem families. Names follow lcp/<solver>/<problem>/<n>, so
// e.g. --benchmark_filter='lcp/pgs/.*' selects one solver and '.*/contact_sparse/.*' one family.
// The benchmark time is the time of one solve (problem generation is outside the timed loop).
// Counters: solver_iterations (pivots, sweeps, Newton steps or bases; named so as not to clash
// with Google Benchmark's own "iterations" column), residual ‖min(z, Mz+q)‖∞,
// converged (1/0), contacts (= n), seconds_per_iteration (CPU time of a solve / its iterations).
//
// Families:
//   spd_dense       M = AᵀA + I dense (random_spd_problem), q ~ N(0, 1)
//   pmatrix_dense   non-symmetric P-matrix M = AᵀA + I + K − Kᵀ (pivoting and Newton only)
//   contact_sparse  M = J Jᵀ + 0.01 I sparse, 6 nonzeros per row of J
//   (random_sparse_contact_problem) murty           Murty's problem as stated (upper triangular, q
//   = −1): 2 Lemke pivots murty_reversed  the same with indices reversed: 2^n Lemke pivots with our
//   tie-break
// Sizes are limited where a method is too slow to keep the default run under two minutes:
// dense problems stop at n = 1000 (Lemke is O(n³) there), enumeration at n = 12.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "solvers/lcp/lcp_solvers.hpp"
#include "solvers/lcp/lcp_test_problems.hpp"

namespace {

using impactbench::solvers::LcpProblem;
using impactbench::solvers::SolverOptions;
using impactbench::solvers::SolverResult;
namespace lcp = impactbench::solvers::lcp;

constexpr std::uint64_t kSeed = 20261121;

struct Family {
  std::string name;
  std::function<LcpProblem(int)> make;
};

const std::vector<Family>& families() {
  static const std::vector<Family> list = {
      {"spd_dense", [](int n) { return lcp::random_spd_problem(n, kSeed); }},
      {"pmatrix_dense", [](int n) { return lcp::random_nonsymmetric_pd_problem(n, kSeed); }},
      {"contact_sparse", [](int n) { return lcp::random_sparse_contact_problem(n, kSeed); }},
      {"contact_sparse_shuffled",
       [](int n) {
         return lcp::random_sparse_contact_problem(n, kSeed, 1e-2, 4, lcp::ContactOrder::kRandom);
       }},
      {"murty", [](int n) { return lcp::murty_problem(n); }},
      {"murty_reversed", [](int n) { return lcp::reversed_murty_problem(n); }},
  };
  return list;
}

// Problems are built once per (family, n) and shared by every solver's run.
const LcpProblem& problem(const Family& family, int n) {
  static std::map<std::pair<std::string, int>, LcpProblem> cache;
  const auto key = std::make_pair(family.name, n);
  auto it = cache.find(key);
  if (it == cache.end()) it = cache.emplace(key, family.make(n)).first;
  return it->second;
}

SolverOptions options_for(const std::string& solver, const std::string& family, int n) {
  SolverOptions options;
  if (solver == "pgs" || solver == "psor") {
    options.tolerance = 1e-8;
    options.max_iterations = 20000;
    options.relaxation = 1.3;  // PSOR only
  } else if (solver == "lemke") {
    options.tolerance = 1e-10;
    options.max_iterations = family.starts_with("murty") ? (1 << n) + 10 : 20 * n + 100;
  } else if (solver == "newton-fb") {
    options.tolerance = 1e-10;
    options.max_iterations = 200;
  } else {
    options.tolerance = 1e-10;
  }
  return options;
}

void run_solver(benchmark::State& state, const std::string& solver, const Family& family, int n) {
  const LcpProblem& p = problem(family, n);
  const SolverOptions options = options_for(solver, family.name, n);
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
    const Family* family = nullptr;
    for (const Family& f : families()) {
      if (f.name == plan.family) family = &f;
    }
    for (int n : plan.sizes) {
      const std::string name = "lcp/" + plan.solver + "/" + plan.family + "/" + std::to_string(n);
      benchmark::RegisterBenchmark(name.c_str(), [solver = plan.solver, family,
                                                  n](benchmark::State& state) {
        run_solver(state, solver, *family, n);
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
