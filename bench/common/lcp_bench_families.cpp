#include "common/lcp_bench_families.hpp"

#include <cstdint>
#include <functional>
#include <map>
#include <stdexcept>
#include <utility>

#include "tests/support/solvers/lcp_test_problems.hpp"

namespace impactbench::bench {
namespace {

constexpr std::uint64_t kSeed = 20261121;

solvers::LcpProblem make_problem(const std::string& family, int n) {
  namespace lcp = solvers::lcp;
  if (family == "spd_dense") return lcp::random_spd_problem(n, kSeed);
  if (family == "pmatrix_dense") return lcp::random_nonsymmetric_pd_problem(n, kSeed);
  if (family == "contact_sparse") return lcp::random_sparse_contact_problem(n, kSeed);
  if (family == "contact_sparse_shuffled") {
    return lcp::random_sparse_contact_problem(n, kSeed, 1e-2, 4, lcp::ContactOrder::kRandom);
  }
  if (family == "murty") return lcp::murty_problem(n);
  if (family == "murty_reversed") return lcp::reversed_murty_problem(n);
  throw std::invalid_argument("unknown LCP benchmark family '" + family + "'");
}

}  // namespace

const solvers::LcpProblem& lcp_family_problem(const std::string& family, int n) {
  static std::map<std::pair<std::string, int>, solvers::LcpProblem> cache;
  const auto key = std::make_pair(family, n);
  auto it = cache.find(key);
  if (it == cache.end()) it = cache.emplace(key, make_problem(family, n)).first;
  return it->second;
}

solvers::SolverOptions lcp_bench_options(const std::string& solver, const std::string& family,
                                         int n) {
  solvers::SolverOptions options;
  // The benchmarks time the solves themselves; the driver's own timer (two clock reads per
  // solve) would be counted in their time.
  options.measure_seconds = false;
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

}  // namespace impactbench::bench
