// The LCP driver: one registry table, one validation, one residual for every method.
#include "solvers/lcp/lcp_solvers.hpp"
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

const std::vector<LcpRegistryEntry>& registry() {
  static const std::vector<LcpRegistryEntry> entries = {
      {{"lemke", "Lemke complementary pivoting, covering vector 1, lexicographic ratio test", 1e-10,
        10000, false},
       lcp::solve_lemke},
      {{"pgs", "projected Gauss-Seidel sweeps (needs M_ii > 0; converges for SPD M)", 1e-8, 10000,
        true},
       lcp::solve_pgs},
      {{"psor", "projected SOR sweeps with relaxation omega in (0, 2)", 1e-8, 10000, true},
       lcp::solve_psor},
      {{"newton-fb", "semismooth Newton on Fischer-Burmeister, Armijo line search", 1e-10, 100,
        true},
       lcp::solve_newton_fb},
      {{"enum", "enumeration of all 2^n complementary bases (n <= 14, test oracle)", 1e-10,
        1 << lcp::kMaxEnumerationSize, false},
       lcp::solve_enumeration},
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
std::string size_error(const LcpProblem& problem, const Eigen::VectorXd* warm_start) {
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

std::string non_finite_error(const LcpProblem& problem, const Eigen::VectorXd* warm_start) {
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
  if (warm_start != nullptr && !warm_start->allFinite()) return "warm start is not finite";
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

SolverResult rejected(SolverStatus status, std::string message, Eigen::Index n) {
  SolverResult result;
  result.status = status;
  result.message = std::move(message);
  result.solution = Eigen::VectorXd::Zero(n);
  result.residual = std::numeric_limits<double>::quiet_NaN();
  return result;
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
                       const SolverOptions& options, const Eigen::VectorXd* warm_start) {
  const LcpRegistryEntry& entry = find_entry(solver);
  const Eigen::Index n = problem.q.size();
  if (std::string e = size_error(problem, warm_start); !e.empty()) {
    return rejected(SolverStatus::kInvalidProblem, std::move(e), n);
  }
  if (std::string e = non_finite_error(problem, warm_start); !e.empty()) {
    return rejected(SolverStatus::kNonFiniteData, std::move(e), n);
  }
  if (std::string e = options_error(options); !e.empty()) {
    return rejected(SolverStatus::kInvalidProblem, std::move(e), n);
  }

  const auto start = std::chrono::steady_clock::now();
  lcp::LcpMethodResult outcome;
  if ((problem.q.array() >= 0.0).all()) {
    // z = 0, w = q ≥ 0 is a solution (for n = 0 trivially).
    outcome.z = Eigen::VectorXd::Zero(n);
    outcome.status = SolverStatus::kConverged;
  } else {
    // Pivoting methods start from no z (and are given none).
    const Eigen::VectorXd z_start = !entry.info.iterative ? Eigen::VectorXd()
                                    : warm_start != nullptr
                                        ? Eigen::VectorXd(warm_start->cwiseMax(0.0))
                                        : Eigen::VectorXd::Zero(n);
    outcome = entry.method(problem, options, z_start);
  }
  const auto stop = std::chrono::steady_clock::now();

  SolverResult result;
  result.seconds = std::chrono::duration<double>(stop - start).count();
  result.solution = std::move(outcome.z);
  if (outcome.w.size() == n && outcome.w.size() == result.solution.size()) {
    result.velocity = std::move(outcome.w);
    result.residual = outcome.residual;
  } else {
    result.velocity = lcp::lcp_velocity(problem, result.solution);
    result.residual = lcp::natural_map_residual(result.solution, result.velocity);
  }
  result.iterations = outcome.iterations;
  result.status = outcome.status;
  result.message = std::move(outcome.message);
  // A method's claim of convergence is only trusted if the common residual confirms it.
  if (result.status == SolverStatus::kConverged && !(result.residual <= options.tolerance)) {
    result.status = result.iterations >= options.max_iterations ? SolverStatus::kMaxIterations
                                                                : SolverStatus::kStalled;
    result.message = entry.info.name + " stopped with residual " +
                     output::number_text(result.residual) + " above tolerance " +
                     output::number_text(options.tolerance);
  }
  return result;
}

}  // namespace impactbench::solvers
