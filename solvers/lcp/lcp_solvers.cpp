// The LCP driver: one registry table, one validation, one residual for every method.
#include "solvers/lcp/lcp_solvers.hpp"
#include "solvers/common/all_finite.hpp"
#include "solvers/common/number_text.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "solvers/lcp/lcp_methods.hpp"
#include "solvers/lcp/lcp_residual.hpp"

namespace impactbench::solvers {
namespace {

struct LcpRegistryEntry {
  SolverInfo info;
  lcp::LcpMethod method;
};

/// A method that returns a fresh result, called as an LcpMethod (its answer replaces the
/// storage it was offered).
template <lcp::LcpMethodResult (*method)(const LcpProblem&, const SolverOptions&, VectorView)>
void fresh(const LcpProblem& problem, const SolverOptions& options, VectorView z_start,
           lcp::LcpMethodResult& result) {
  result = method(problem, options, z_start);
}

const std::vector<LcpRegistryEntry>& registry() {
  static const std::vector<LcpRegistryEntry> entries = {
      {{"lemke", "Lemke complementary pivoting, covering vector 1, lexicographic ratio test", 1e-10,
        10000, false},
       lcp::solve_lemke},
      {{"pgs", "projected Gauss-Seidel sweeps (needs M_ii > 0; converges for SPD M)", 1e-8, 10000,
        true},
       fresh<lcp::solve_pgs>},
      {{"psor", "projected SOR sweeps with relaxation omega in (0, 2)", 1e-8, 10000, true},
       fresh<lcp::solve_psor>},
      {{"newton-fb", "semismooth Newton on Fischer-Burmeister, Armijo line search", 1e-10, 100,
        true},
       fresh<lcp::solve_newton_fb>},
      {{"enum", "enumeration of all 2^n complementary bases (n <= 14, test oracle)", 1e-10,
        1 << lcp::kMaxEnumerationSize, false},
       fresh<lcp::solve_enumeration>},
  };
  return entries;
}

const LcpRegistryEntry& find_entry(std::string_view name) {
  std::string known;
  for (const auto& entry : registry()) {
    if (entry.info.name == name) return entry;
    known += (known.empty() ? "" : ", ") + entry.info.name;
  }
  throw std::invalid_argument("unknown LCP solver '" + std::string(name) +
                              "'; known solvers: " + known);
}

// Returns an empty string when the problem is well formed, else what is wrong.
std::string size_error(const LcpProblem& problem, WarmStart warm_start) {
  const Eigen::Index n = problem.q.size();
  const Eigen::Index rows = problem.is_sparse ? problem.sparse_M.rows() : problem.dense_M.rows();
  const Eigen::Index cols = problem.is_sparse ? problem.sparse_M.cols() : problem.dense_M.cols();
  if (rows != n || cols != n) {
    return "M is " + std::to_string(rows) + "x" + std::to_string(cols) + " but q has " +
           std::to_string(n) + " entries";
  }
  if (warm_start != nullptr && warm_start->size() != n) {
    return "warm start has " + std::to_string(warm_start->size()) + " entries, expected " +
           std::to_string(n);
  }
  return {};
}

// Checked at the cost of a vectorised sum (all_finite); only a problem that fails is searched
// for the entry to name.
std::string non_finite_error(const LcpProblem& problem, WarmStart warm_start) {
  const bool matrix_finite =
      problem.is_sparse ? all_finite(problem.sparse_M.valuePtr(), problem.sparse_M.nonZeros())
                        : all_finite(problem.dense_M);
  if (all_finite(problem.q) && matrix_finite) {
    return warm_start != nullptr && !all_finite(*warm_start) ? "warm start is not finite" : "";
  }
  for (Eigen::Index i = 0; i < problem.q.size(); ++i) {
    if (!std::isfinite(problem.q(i))) return "q(" + std::to_string(i) + ") is not finite";
  }
  if (problem.is_sparse) {
    for (int k = 0; k < problem.sparse_M.outerSize(); ++k) {
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(problem.sparse_M, k); it;
           ++it) {
        if (!std::isfinite(it.value())) {
          return "M(" + std::to_string(it.row()) + "," + std::to_string(it.col()) +
                 ") is not finite";
        }
      }
    }
  } else {
    for (Eigen::Index j = 0; j < problem.dense_M.cols(); ++j) {
      for (Eigen::Index i = 0; i < problem.dense_M.rows(); ++i) {
        if (!std::isfinite(problem.dense_M(i, j))) {
          return "M(" + std::to_string(i) + "," + std::to_string(j) + ") is not finite";
        }
      }
    }
  }
  return {};
}

std::string options_error(const SolverOptions& options) {
  if (!(options.tolerance > 0.0) || !std::isfinite(options.tolerance)) {
    return "tolerance " + output::number_text(options.tolerance) + " must be positive and finite";
  }
  if (options.max_iterations < 0) {
    return "max_iterations " + std::to_string(options.max_iterations) + " must be >= 0";
  }
  return {};
}

void reject(SolverStatus status, std::string message, Eigen::Index n, SolverResult& result) {
  result.status = status;
  result.message = std::move(message);
  result.solution.setZero(n);
  result.velocity.resize(0);
  result.iterations = 0;
  result.residual = std::numeric_limits<double>::quiet_NaN();
  result.faceted_residual = std::numeric_limits<double>::quiet_NaN();
  result.seconds = 0.0;
}

}  // namespace

const std::vector<SolverInfo>& lcp_solvers() {
  static const std::vector<SolverInfo> infos = [] {
    std::vector<SolverInfo> list;
    for (const auto& entry : registry()) list.push_back(entry.info);
    return list;
  }();
  return infos;
}

SolverResult solve_lcp(const LcpProblem& problem, std::string_view solver,
                       const SolverOptions& options, WarmStart warm_start) {
  SolverResult result;
  solve_lcp(problem, solver, options, warm_start, result);
  return result;
}

void solve_lcp(const LcpProblem& problem, std::string_view solver, const SolverOptions& options,
               WarmStart warm_start, SolverResult& result) {
  const LcpRegistryEntry& entry = find_entry(solver);
  const Eigen::Index n = problem.q.size();
  if (std::string e = size_error(problem, warm_start); !e.empty()) {
    return reject(SolverStatus::kInvalidProblem, std::move(e), n, result);
  }
  if (std::string e = non_finite_error(problem, warm_start); !e.empty()) {
    return reject(SolverStatus::kNonFiniteData, std::move(e), n, result);
  }
  if (std::string e = options_error(options); !e.empty()) {
    return reject(SolverStatus::kInvalidProblem, std::move(e), n, result);
  }

  const auto start = options.measure_seconds ? std::chrono::steady_clock::now()
                                             : std::chrono::steady_clock::time_point{};
  // The method may reuse the storage of the caller's last answer.
  lcp::LcpMethodResult outcome;
  outcome.z.swap(result.solution);
  outcome.w.swap(result.velocity);
  outcome.message.swap(result.message);
  outcome.message.clear();
  if ((problem.q.array() >= 0.0).all()) {
    // z = 0, w = q ≥ 0 is a solution (for n = 0 trivially).
    outcome.z.setZero(n);
    outcome.status = SolverStatus::kConverged;
  } else {
    // Pivoting methods start from no z (and are given none).
    const Eigen::VectorXd z_start = !entry.info.iterative ? Eigen::VectorXd()
                                    : warm_start != nullptr
                                        ? Eigen::VectorXd(warm_start->cwiseMax(0.0))
                                        : Eigen::VectorXd::Zero(n);
    entry.method(problem, options, z_start, outcome);
  }
  result.seconds =
      options.measure_seconds
          ? std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
          : std::numeric_limits<double>::quiet_NaN();
  result.solution.swap(outcome.z);
  result.velocity.swap(outcome.w);
  if (outcome.has_velocity) {
    result.residual = outcome.residual;
  } else {
    lcp::write_lcp_velocity(problem, result.solution, result.velocity);
    result.residual = lcp::natural_map_residual(result.solution, result.velocity);
  }
  result.faceted_residual = std::numeric_limits<double>::quiet_NaN();
  result.iterations = outcome.iterations;
  result.status = outcome.status;
  result.message.swap(outcome.message);
  // A method's claim of convergence is only trusted if the common residual confirms it.
  if (result.status == SolverStatus::kConverged && !(result.residual <= options.tolerance)) {
    result.status = result.iterations >= options.max_iterations ? SolverStatus::kMaxIterations
                                                                : SolverStatus::kStalled;
    result.message = entry.info.name + " stopped with residual " +
                     output::number_text(result.residual) + " above tolerance " +
                     output::number_text(options.tolerance);
  }
}

}  // namespace impactbench::solvers
